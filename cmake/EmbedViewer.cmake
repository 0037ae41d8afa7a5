# Compiles the replay viewer's files (viewer/viewer.html, viewer.js, viewer.css) into a C++ source
# defining hullinspect::io::detail::kViewerHtml / kViewerJs / kViewerCss, so `hullinspect view` and
# `run --html` work from any directory. Editing a viewer file re-runs the configure step.
function(hullinspect_embed_viewer viewer_dir output)
  set(delimiter "HIVIEW")
  set(body "")
  foreach(pair "html;kViewerHtml;viewer.html" "js;kViewerJs;viewer.js" "css;kViewerCss;viewer.css")
    list(GET pair 1 symbol)
    list(GET pair 2 name)
    set(input ${viewer_dir}/${name})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${input})
    file(READ ${input} text)
    string(FIND "${text}" ")${delimiter}\"" clash)
    if(NOT clash EQUAL -1)
      message(FATAL_ERROR "${input} contains the raw-string delimiter )${delimiter}\"")
    endif()
    # The script and style are inlined into the page: they must not close their element early.
    string(TOLOWER "${text}" lower)
    if(name STREQUAL "viewer.js")
      string(FIND "${lower}" "</script" early)
    elseif(name STREQUAL "viewer.css")
      string(FIND "${lower}" "</style" early)
    else()
      set(early -1)
    endif()
    if(NOT early EQUAL -1)
      message(FATAL_ERROR "${input} must not contain a closing </script or </style tag")
    endif()
    string(APPEND body
           "extern const std::string_view ${symbol};\n"
           "const std::string_view ${symbol} = R\"${delimiter}(${text})${delimiter}\";\n")
  endforeach()
  file(WRITE ${output}.tmp
       "// Generated from viewer/ by cmake/EmbedViewer.cmake; do not edit.\n"
       "#include <string_view>\n"
       "namespace hullinspect::io::detail {\n"
       "${body}"
       "}  // namespace hullinspect::io::detail\n")
  file(COPY_FILE ${output}.tmp ${output} ONLY_IF_DIFFERENT)
endfunction()
