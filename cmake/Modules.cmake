# The library is one static library per module: hullinspect_<module> holds src/<module>/*.cpp (its
# public headers are include/hullinspect/<module>/) and links only the modules it declares with
# USES, so the linker sees each module before the ones below it. hullinspect_check_layers (below)
# fails the build on an #include "hullinspect/<module>/..." of a module that is not below the
# includer. The declarations are the one dependency table: hullinspect_module records each in the
# global property HULLINSPECT_LAYERS ("module=use1,use2") that the check passes to
# tools/check_layers.py.
#
#   hullinspect_module(NAME [USES module...] [SOURCES generated.cpp...])

# The Python module (python/) links the library into a shared object, so its static libraries are
# compiled as position-independent code then; -fno-semantic-interposition keeps GCC inlining
# across them as it does for the executable's -fPIE.
function(hullinspect_linkable_into_python target)
  if(HULLINSPECT_WITH_PYTHON)
    set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
    target_compile_options(${target} PRIVATE -fno-semantic-interposition)
  endif()
endfunction()

function(hullinspect_module name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "" "USES;SOURCES")
  file(GLOB sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/${name}/*.cpp)
  add_library(hullinspect_${name} STATIC ${sources} ${arg_SOURCES})
  foreach(used ${arg_USES})
    if(NOT TARGET hullinspect_${used})
      message(FATAL_ERROR "module ${name} uses ${used}, which is not declared before it")
    endif()
    target_link_libraries(hullinspect_${name} PUBLIC hullinspect_${used})
  endforeach()
  hullinspect_linkable_into_python(hullinspect_${name})
  list(JOIN arg_USES "," uses)
  set_property(GLOBAL APPEND PROPERTY HULLINSPECT_LAYERS "${name}=${uses}")
endfunction()

# After the last module: every build of the library checks the declared table against the
# sources' #include lines (tools/check_layers.py), so an include of a module that is not below the
# includer fails the build with its file and line. Re-run when a source or header changes.
function(hullinspect_check_layers)
  get_property(layers GLOBAL PROPERTY HULLINSPECT_LAYERS)
  file(GLOB_RECURSE sources CONFIGURE_DEPENDS ${CMAKE_SOURCE_DIR}/src/*
       ${CMAKE_SOURCE_DIR}/include/hullinspect/*)
  set(stamp ${CMAKE_BINARY_DIR}/generated/layers.checked)
  add_custom_command(
    OUTPUT ${stamp}
    COMMAND /usr/bin/python3 ${CMAKE_SOURCE_DIR}/tools/check_layers.py --source ${CMAKE_SOURCE_DIR}
            ${layers}
    COMMAND ${CMAKE_COMMAND} -E touch ${stamp}
    DEPENDS ${CMAKE_SOURCE_DIR}/tools/check_layers.py ${sources}
    COMMENT "Checking that every module includes only the modules below it"
    VERBATIM)
  add_custom_target(hullinspect_layers DEPENDS ${stamp})
  foreach(entry ${layers})
    string(REGEX REPLACE "=.*" "" name "${entry}")
    add_dependencies(hullinspect_${name} hullinspect_layers)
  endforeach()
endfunction()
