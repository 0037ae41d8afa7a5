#include "hullinspect/io/viewer_html.hpp"

#include <algorithm>
#include <array>
#include <string_view>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::io {

namespace detail {
extern const std::string_view kViewerHtml;
extern const std::string_view kViewerJs;
extern const std::string_view kViewerCss;
extern const std::string_view kViewerThreeJs;
}  // namespace detail

namespace {

// The parts of viewer/viewer.html that load the style, the scripts and a trace when the page is
// opened from the source tree; the generated page replaces each with inline content. The scripts
// sit between two comments (cmake/EmbedViewer.cmake concatenates them in the listed order).
constexpr std::string_view kStyleLink = R"(<link rel="stylesheet" href="viewer.css">)";
constexpr std::string_view kScriptsBegin = "<!-- viewer scripts";
constexpr std::string_view kScriptsEnd = "<!-- end of viewer scripts -->";
constexpr std::string_view kTraceSlot =
    R"(<script type="application/json" id="trace-data"></script>)";
// Where three.js goes when the page can show 3D: before the viewer's scripts, which find it as the
// global THREE_VIEW; the page's start-up options go in the same place.
constexpr std::string_view kThreeSlot = "<!-- three.js -->";

// JSON text that is safe inside a <script> element: '<' only occurs inside JSON strings, where the
// escape \u003c means the same character, so "</script>" or "<!--" can never appear.
std::string script_safe_json(const nlohmann::json& trace) {
  const std::string text = trace.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size() + text.size() / 64);
  for (char c : text) {
    if (c == '<') {
      out += "\\u003c";
    } else {
      out += c;
    }
  }
  return out;
}

}  // namespace

bool viewer_has_3d() {
  return !detail::kViewerThreeJs.empty();
}

bool trace_has_3d_geometry(const nlohmann::json& trace) {
  return trace.is_object() && trace.contains("ship_frame") && trace["ship_frame"].is_object();
}

std::string viewer_html(const nlohmann::json& trace, const ViewerOptions& options) {
  const bool geometry = trace_has_3d_geometry(trace);
  if (options.start_3d && !geometry) {
    throw ParameterError("3d",
                         "the trace's hull is a mask without 3D geometry (no ship_frame); the 3D "
                         "view needs a hull imported from a mesh (hullinspect hull import)");
  }
  if (options.start_3d && !viewer_has_3d()) {
    throw Error(
        "--3d: this hullinspect was built without the viewer's 3D view "
        "(viewer/node_modules missing: run scripts/setup, then configure again)");
  }
  std::string three_content = R"(<script type="application/json" id="view-options">{"start_3d":)" +
                              std::string(options.start_3d ? "true" : "false") + "}</script>";
  if (geometry && viewer_has_3d()) {
    three_content += "\n<script>\n" + std::string(detail::kViewerThreeJs) + "\n</script>";
  }
  // Each slot is the text [at, at + size) of the page, replaced by `content`.
  struct Slot {
    std::string_view begin;
    std::string_view end;  // empty: the slot is `begin` itself
    std::string content;
    std::size_t at = std::string_view::npos;
    std::size_t size = 0;
  };
  std::array<Slot, 4> slots{{
      {kThreeSlot, {}, std::move(three_content)},
      {kStyleLink, {}, "<style>\n" + std::string(detail::kViewerCss) + "</style>"},
      {kScriptsBegin, kScriptsEnd, "<script>\n" + std::string(detail::kViewerJs) + "</script>"},
      {kTraceSlot,
       {},
       R"(<script type="application/json" id="trace-data">)" + script_safe_json(trace) +
           "</script>"},
  }};
  const std::string_view page = detail::kViewerHtml;
  for (auto& slot : slots) {
    slot.at = page.find(slot.begin);
    const auto end = slot.end.empty() ? slot.at : page.find(slot.end, slot.at);
    if (slot.at == std::string_view::npos || end == std::string_view::npos) {
      throw LogicError("viewer/viewer.html lacks " + std::string(slot.begin));
    }
    slot.size = end + (slot.end.empty() ? slot.begin.size() : slot.end.size()) - slot.at;
  }
  std::sort(slots.begin(), slots.end(), [](const Slot& a, const Slot& b) { return a.at < b.at; });
  std::string html;
  std::size_t size = page.size();
  for (const auto& slot : slots) size += slot.content.size();
  html.reserve(size);
  std::size_t from = 0;
  for (const auto& slot : slots) {
    html.append(page.substr(from, slot.at - from));
    html.append(slot.content);
    from = slot.at + slot.size;
  }
  html.append(page.substr(from));
  return html;
}

}  // namespace hullinspect::io
