// The HTML replay: one self-contained page holding the viewer and the trace, whatever the trace's
// strings contain.

#include <gtest/gtest.h>

#include "hullinspect/io/viewer_html.hpp"

namespace hullinspect::io {
namespace {

using nlohmann::json;

constexpr std::string_view kTraceOpen = R"(<script type="application/json" id="trace-data">)";

std::size_t count(const std::string& text, std::string_view what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The JSON text inside the trace element, read back as a browser would (textContent + JSON.parse).
json embedded_trace(const std::string& html) {
  const auto begin = html.find(kTraceOpen);
  EXPECT_NE(begin, std::string::npos);
  const auto from = begin + kTraceOpen.size();
  const auto end = html.find("</script>", from);
  EXPECT_NE(end, std::string::npos);
  return json::parse(html.substr(from, end - from));
}

TEST(ViewerHtml, IsOneSelfContainedPage) {
  const json trace = {{"format", "hullinspect-trace"}, {"frames", json::array({{{"t", 0}}})}};
  const std::string html = viewer_html(trace);
  EXPECT_EQ(html.rfind("<!doctype html>", 0), 0u);
  EXPECT_EQ(count(html, "<style>"), 1u);
  EXPECT_EQ(count(html, "</style>"), 1u);
  EXPECT_EQ(count(html, "<script"), 2u);  // the viewer and the trace
  EXPECT_EQ(count(html, "</script>"), 2u);
  // Nothing is loaded from elsewhere: no src/href attributes, no URLs.
  EXPECT_EQ(count(html, " src="), 0u);
  EXPECT_EQ(count(html, " href="), 0u);
  EXPECT_EQ(count(html, "http://"), 0u);
  EXPECT_EQ(count(html, "https://"), 0u);
  EXPECT_NE(html.find("class Replay"), std::string::npos);  // the viewer's script is inlined
  EXPECT_EQ(embedded_trace(html), trace);
}

TEST(ViewerHtml, TraceStringsCannotCloseTheScriptElement) {
  const json trace = {{"parameters",
                       {{"hull", "</script><script>alert(1)</script>"},
                        {"note", "<!-- <script> -->"},
                        {"unicode", "Zürich — 5 µm ≤ 2 m"}}},
                      {"format", "hullinspect-trace"}};
  const std::string html = viewer_html(trace);
  EXPECT_EQ(count(html, "</script"), 2u);
  EXPECT_EQ(count(html, "<!--"), count(viewer_html(json::object()), "<!--"));
  EXPECT_EQ(embedded_trace(html), trace);
}

}  // namespace
}  // namespace hullinspect::io
