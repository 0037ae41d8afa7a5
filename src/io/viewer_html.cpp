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
}  // namespace detail

namespace {

// The lines of viewer/viewer.html that load the script, the style and a trace when the page is
// opened from the source tree; the generated page replaces each with inline content.
constexpr std::string_view kStyleLink = R"(<link rel="stylesheet" href="viewer.css">)";
constexpr std::string_view kScriptLink = R"(<script src="viewer.js"></script>)";
constexpr std::string_view kTraceSlot = R"(<script type="application/json" id="trace-data"></script>)";

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

std::string viewer_html(const nlohmann::json& trace) {
  struct Slot {
    std::string_view marker;
    std::string content;
    std::size_t at = std::string_view::npos;
  };
  std::array<Slot, 3> slots{{
      {kStyleLink, "<style>\n" + std::string(detail::kViewerCss) + "</style>"},
      {kScriptLink, "<script>\n" + std::string(detail::kViewerJs) + "</script>"},
      {kTraceSlot, R"(<script type="application/json" id="trace-data">)" +
                       script_safe_json(trace) + "</script>"},
  }};
  const std::string_view page = detail::kViewerHtml;
  for (auto& slot : slots) {
    slot.at = page.find(slot.marker);
    if (slot.at == std::string_view::npos) {
      throw LogicError("viewer/viewer.html lacks the line " + std::string(slot.marker));
    }
  }
  std::sort(slots.begin(), slots.end(), [](const Slot& a, const Slot& b) { return a.at < b.at; });
  std::string html;
  html.reserve(page.size() + slots[0].content.size() + slots[1].content.size() +
               slots[2].content.size());
  std::size_t from = 0;
  for (const auto& slot : slots) {
    html.append(page.substr(from, slot.at - from));
    html.append(slot.content);
    from = slot.at + slot.marker.size();
  }
  html.append(page.substr(from));
  return html;
}

}  // namespace hullinspect::io
