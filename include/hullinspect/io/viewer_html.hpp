#pragma once
// The self-contained HTML replay of a mission (docs/viewer.md): the viewer's page, script and style
// (viewer/, compiled into the library by cmake/EmbedViewer.cmake) with the trace embedded.

#include <nlohmann/json.hpp>

#include <string>

namespace hullinspect::io {

/// How the page opens.
struct ViewerOptions {
  bool start_3d = false;  // open in the 3D view (the trace must place its hull in the ship frame)
};

/// Whether this build carries three.js for the 3D view (cmake/EmbedViewer.cmake).
bool viewer_has_3d();

/// Whether the 3D view can show `trace`: a hull imported from a mesh, whose trace has `ship_frame`.
bool trace_has_3d_geometry(const nlohmann::json& trace);

/// One HTML document holding the viewer and `trace`; it loads nothing from the network or disk.
/// The trace sits in a <script type="application/json"> element with every '<' written as \u003c,
/// so no string in the trace can close the element. three.js (about 0.57 MB) is inlined only for a
/// trace with 3D geometry. Throws ParameterError("3d", ...) when options.start_3d is asked for a
/// trace without it, Error when this build lacks the 3D view.
std::string viewer_html(const nlohmann::json& trace, const ViewerOptions& options = {});

}  // namespace hullinspect::io
