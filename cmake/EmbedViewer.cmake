# Compiles the replay viewer (viewer/viewer.html, viewer.css and the scripts viewer.html lists
# between "<!-- viewer scripts" and "<!-- end of viewer scripts -->", in that order) into a C++
# source defining hullinspect::io::detail::kViewerHtml / kViewerJs / kViewerCss, so
# `hullinspect view` and `run --html` work from any directory. Editing a viewer file re-runs the
# configure step.
#
# kViewerThreeJs is three.js (viewer/package.json, installed by scripts/setup with `npm ci`) as
# one classic script defining the global THREE_VIEW: esbuild bundles viewer/three_bundle.js here,
# at configure time, so neither the build nor the page downloads anything. Without
# viewer/node_modules it is empty and the viewer's 3D view is unavailable (a warning says so).
# Stops the configure step when `file`'s text holds `closing` (any case): the page would end early.
function(hullinspect_check_inlinable file text closing)
  string(TOLOWER "${text}" lower)
  string(FIND "${lower}" "${closing}" early)
  if(NOT early EQUAL -1)
    message(FATAL_ERROR "${file} must not contain ${closing}: it is inlined into the page")
  endif()
endfunction()

function(hullinspect_bundle_three viewer_dir output_var)
  set(entry ${viewer_dir}/three_bundle.js)
  set(esbuild ${viewer_dir}/node_modules/esbuild/bin/esbuild)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${entry}
                                                                 ${viewer_dir}/package-lock.json)
  # bin/esbuild is the native binary once npm ran esbuild's install step, else a node script.
  if(NOT EXISTS ${esbuild} OR NOT EXISTS ${viewer_dir}/node_modules/three)
    message(WARNING "viewer/node_modules lacks three or esbuild (run scripts/setup): "
                    "the replay viewer is built without its 3D view")
    set(${output_var} "" PARENT_SCOPE)
    return()
  endif()
  set(bundle ${CMAKE_BINARY_DIR}/generated/three_view.js)
  execute_process(
    COMMAND ${esbuild} ${entry} --bundle --minify --format=iife
            --global-name=THREE_VIEW --legal-comments=inline --log-level=warning
            --outfile=${bundle}
    WORKING_DIRECTORY ${viewer_dir}
    RESULT_VARIABLE status)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "esbuild could not bundle ${entry} (exit ${status})")
  endif()
  file(READ ${bundle} text)
  hullinspect_check_inlinable(${bundle} "${text}" "</script")
  set(${output_var} "${text}" PARENT_SCOPE)
endfunction()

function(hullinspect_embed_viewer viewer_dir output)
  set(delimiter "HIVIEW")
  hullinspect_bundle_three(${viewer_dir} three)
  # The page, the style and every script, with the checks inlining needs.
  set(html_file ${viewer_dir}/viewer.html)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${html_file})
  file(READ ${html_file} html)
  string(REGEX MATCH "<!-- viewer scripts[^>]*-->.*<!-- end of viewer scripts -->" block "${html}")
  if(NOT block)
    message(FATAL_ERROR "${html_file} lacks the <!-- viewer scripts … end of viewer scripts --> block")
  endif()
  string(REGEX MATCHALL "<script src=\"[^\"]+\"></script>" tags "${block}")
  set(js "")
  foreach(tag ${tags})
    string(REGEX REPLACE "<script src=\"([^\"]+)\"></script>" "\\1" name "${tag}")
    set(script ${viewer_dir}/${name})
    set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${script})
    file(READ ${script} text)
    hullinspect_check_inlinable(${script} "${text}" "</script")
    string(APPEND js "// ---- viewer/${name}\n${text}\n")
  endforeach()
  set(css_file ${viewer_dir}/viewer.css)
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${css_file})
  file(READ ${css_file} css)
  hullinspect_check_inlinable(${css_file} "${css}" "</style")

  set(body "")
  foreach(pair "kViewerHtml;html" "kViewerJs;js" "kViewerCss;css" "kViewerThreeJs;three")
    list(GET pair 0 symbol)
    list(GET pair 1 variable)
    string(FIND "${${variable}}" ")${delimiter}\"" clash)
    if(NOT clash EQUAL -1)
      message(FATAL_ERROR "a viewer file contains the raw-string delimiter )${delimiter}\"")
    endif()
    string(APPEND body
           "extern const std::string_view ${symbol};\n"
           "const std::string_view ${symbol} = R\"${delimiter}(${${variable}})${delimiter}\";\n")
  endforeach()
  file(WRITE ${output}.tmp
       "// Generated from viewer/ by cmake/EmbedViewer.cmake; do not edit.\n"
       "#include <string_view>\n"
       "namespace hullinspect::io::detail {\n"
       "${body}"
       "}  // namespace hullinspect::io::detail\n")
  file(COPY_FILE ${output}.tmp ${output} ONLY_IF_DIFFERENT)
endfunction()
