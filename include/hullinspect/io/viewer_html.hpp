#pragma once
// The self-contained HTML replay of a mission (docs/viewer.md): the viewer's page, script and style
// (viewer/, compiled into the library by cmake/EmbedViewer.cmake) with the trace embedded.

#include <nlohmann/json.hpp>

#include <string>

namespace hullinspect::io {

/// One HTML document holding the viewer and `trace`; it loads nothing from the network or disk.
/// The trace sits in a <script type="application/json"> element with every '<' written as \u003c,
/// so no string in the trace can close the element.
std::string viewer_html(const nlohmann::json& trace);

}  // namespace hullinspect::io
