add_library(hullinspect_warnings INTERFACE)
target_compile_options(hullinspect_warnings INTERFACE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                       -Wno-sign-conversion)
# GCC 12 reports false -Wrestrict errors inside libstdc++'s std::string concatenation at -O2/-O3
# (GCC bug 105329); the warning is noise there, so it is off for GCC 12 only.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(hullinspect_warnings INTERFACE -Wno-restrict)
endif()
if(HULLINSPECT_WERROR)
  target_compile_options(hullinspect_warnings INTERFACE -Werror)
endif()
# With HULLINSPECT_FUZZ every object is instrumented for coverage-guided fuzzing (fuzz/ links the
# fuzzer's main into its targets only). The asan preset adds ASan + UBSan (HULLINSPECT_SANITIZE),
# so one sanitizer build serves both the test suite and the brief fuzz runs; the fuzz-campaign
# preset adds only UBSan (HULLINSPECT_FUZZ_UBSAN), several times faster per input, for the long
# campaigns of scripts/fuzz (docs/reliability.md, "Fuzzing").
option(HULLINSPECT_FUZZ_UBSAN "With HULLINSPECT_FUZZ and without HULLINSPECT_SANITIZE: UBSan only (the fuzz-campaign preset)" OFF)
if(HULLINSPECT_FUZZ)
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
if(HULLINSPECT_SANITIZE)
  # Tests give sanitized builds time slack; GCC defines __SANITIZE_ADDRESS__, clang does not.
  add_compile_definitions(HULLINSPECT_SANITIZED)
  add_compile_options(-fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
elseif(HULLINSPECT_FUZZ_UBSAN)
  add_compile_options(-fsanitize=undefined -fno-sanitize-recover=all -fno-omit-frame-pointer)
  add_link_options(-fsanitize=undefined)
endif()
