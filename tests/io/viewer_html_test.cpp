// The HTML replay: one self-contained page holding the viewer and the trace, whatever the trace's
// strings contain.

#include <gtest/gtest.h>

#include "hullinspect/core/errors.hpp"
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
  EXPECT_EQ(count(html, "<script"), 3u);  // the page's options, the viewer and the trace
  EXPECT_EQ(count(html, "</script>"), 3u);
  // Nothing is loaded from elsewhere: no src/href attributes, no URLs.
  EXPECT_EQ(count(html, " src="), 0u);
  EXPECT_EQ(count(html, " href="), 0u);
  EXPECT_EQ(count(html, "http://"), 0u);
  EXPECT_EQ(count(html, "https://"), 0u);
  EXPECT_NE(html.find("class Replay"), std::string::npos);  // the viewer's script is inlined
  EXPECT_EQ(html.find("THREE_VIEW="), std::string::npos);   // three.js only for 3D geometry
  EXPECT_EQ(embedded_trace(html), trace);
}

// A trace whose hull sits in the ship frame (a hull imported from a mesh).
json mesh_trace() {
  return {{"format", "hullinspect-trace"},
          {"ship_frame",
           {{"origin", {0.0, 0.0}},
            {"side_plane_y", 0.0},
            {"side", "starboard"},
            {"depth", {{0.0}}},
            {"normal", {{{0.0, -1.0, 0.0}}}}}}};
}

TEST(ViewerHtml, InlinesThreeJsOnlyForAHullWithGeometry) {
  ASSERT_TRUE(viewer_has_3d()) << "built without viewer/node_modules (run scripts/setup)";
  EXPECT_FALSE(trace_has_3d_geometry(json::object()));
  EXPECT_TRUE(trace_has_3d_geometry(mesh_trace()));
  const std::string html = viewer_html(mesh_trace());
  EXPECT_EQ(count(html, "var THREE_VIEW="), 1u);
  EXPECT_EQ(count(html, "<script"), 4u);  // options, three.js, the viewer, the trace
  EXPECT_EQ(count(html, "</script>"), 4u);
  EXPECT_EQ(count(html, " src="), 0u);
  EXPECT_EQ(count(html, "https://"), 0u);
  // three.js goes before the viewer's scripts, which find it as a global.
  EXPECT_LT(html.find("var THREE_VIEW="), html.find("class Replay"));
  EXPECT_NE(html.find(R"({"start_3d":false})"), std::string::npos);
  EXPECT_NE(viewer_html(mesh_trace(), {.start_3d = true}).find(R"({"start_3d":true})"),
            std::string::npos);
  EXPECT_EQ(embedded_trace(html), mesh_trace());
}

TEST(ViewerHtml, Start3dOnAMaskHullIsAParameterError) {
  const json trace = {{"format", "hullinspect-trace"}};
  try {
    viewer_html(trace, {.start_3d = true});
    FAIL() << "no error";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.name(), "3d");
    EXPECT_NE(e.problem().find("mask"), std::string::npos) << e.problem();
  }
}

TEST(ViewerHtml, TraceStringsCannotCloseTheScriptElement) {
  const json trace = {{"parameters",
                       {{"hull", "</script><script>alert(1)</script>"},
                        {"note", "<!-- <script> -->"},
                        {"unicode", "Zürich — 5 µm ≤ 2 m"}}},
                      {"format", "hullinspect-trace"}};
  const std::string html = viewer_html(trace);
  EXPECT_EQ(count(html, "</script"), 3u);
  EXPECT_EQ(count(html, "<!--"), count(viewer_html(json::object()), "<!--"));
  EXPECT_EQ(embedded_trace(html), trace);
}

}  // namespace
}  // namespace hullinspect::io
