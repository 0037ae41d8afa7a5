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

// The parts of viewer/viewer.html that load the style, the scripts and a trace when the page is
// opened from the source tree; the generated page replaces each with inline content. The scripts
// sit between two comments (cmake/EmbedViewer.cmake concatenates them in the listed order).
constexpr std::string_view kStyleLink = R"(<link rel="stylesheet" href="viewer.css">)";
constexpr std::string_view kScriptsBegin = "<!-- viewer scripts";
constexpr std::string_view kScriptsEnd = "<!-- end of viewer scripts -->";
constexpr std::string_view kTraceSlot =
    R"(<script type="application/json" id="trace-data"></script>)";

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
  // Each slot is the text [at, at + size) of the page, replaced by `content`.
  struct Slot {
    std::string_view begin;
    std::string_view end;  // empty: the slot is `begin` itself
    std::string content;
    std::size_t at = std::string_view::npos;
    std::size_t size = 0;
  };
  std::array<Slot, 3> slots{{
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
  html.reserve(page.size() + slots[0].content.size() + slots[1].content.size() +
               slots[2].content.size());
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
