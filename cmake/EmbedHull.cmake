# Turns a hull mask text file into a C++ source defining hullinspect::world::detail::kDefaultHullText.
function(hullinspect_embed_hull input output)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${input})
  file(READ ${input} HULL_TEXT)
  file(WRITE ${output}.tmp
       "// Generated from data/hulls/default.txt by cmake/EmbedHull.cmake; do not edit.\n"
       "#include <string_view>\n"
       "namespace hullinspect::world::detail {\n"
       "extern const std::string_view kDefaultHullText;\n"
       "const std::string_view kDefaultHullText = R\"HULL(${HULL_TEXT})HULL\";\n"
       "}  // namespace hullinspect::world::detail\n")
  file(COPY_FILE ${output}.tmp ${output} ONLY_IF_DIFFERENT)
endfunction()
