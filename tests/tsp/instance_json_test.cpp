// The segment-TSP instance and solution formats (docs/tsp.md): parsing, exact error messages,
// and what `hullinspect tsp` prints.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/io/tsp_json.hpp"
#include "support/cli_runner.hpp"

namespace hullinspect::io {
namespace {

TEST(TspInstanceJson, ParsesTheDocumentedFormat) {
  const auto p = parse_tsp_instance(
      R"({"start": [3, 4], "segments": [[[0, 2], [9, 2]], [[5, 7], [5, 7]], [[-2, 1], [1000000, 1]]]})",
      "a.json");
  EXPECT_EQ(p.start, (grid::Cell{3, 4}));
  ASSERT_EQ(p.segments.size(), 3u);
  EXPECT_EQ(p.segments[0].first, (grid::Cell{0, 2}));
  EXPECT_EQ(p.segments[0].second, (grid::Cell{9, 2}));
  EXPECT_EQ(p.segments[1].first, p.segments[1].second);
  EXPECT_EQ(p.segments[2].first, (grid::Cell{-2, 1}));
  EXPECT_EQ(p.segments[2].second, (grid::Cell{1000000, 1}));
  EXPECT_TRUE(
      parse_tsp_instance(R"({"segments": [], "start": [0, 0]})", "b.json").segments.empty());
}

TEST(TspInstanceJson, RoundTripsThroughItsJson) {
  const auto p =
      parse_tsp_instance(R"({"start":[1,2],"segments":[[[3,4],[5,4]],[[0,0],[0,0]]]})", "c.json");
  EXPECT_EQ(tsp_instance_json(p).dump(),
            R"({"start":[1,2],"segments":[[[3,4],[5,4]],[[0,0],[0,0]]]})");
}

struct Malformed {
  std::string text;
  std::string message;
};

class TspInstanceErrors : public ::testing::TestWithParam<Malformed> {};

TEST_P(TspInstanceErrors, NameTheFileAndTheField) {
  try {
    parse_tsp_instance(GetParam().text, "bad.json");
    FAIL() << "accepted " << GetParam().text;
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), GetParam().message);
    EXPECT_EQ(e.file(), "bad.json");
  }
}

INSTANTIATE_TEST_SUITE_P(
    Table, TspInstanceErrors,
    ::testing::Values(
        Malformed{"[1, 2]",
                  R"(bad.json: expected a JSON object {"start": [x, y], "segments": [...]})"},
        Malformed{R"({"segments": []})", R"(bad.json: missing "start": [x, y])"},
        Malformed{R"({"start": [0, 0]})",
                  R"(bad.json: missing "segments": [[[x1, y1], [x2, y2]], ...])"},
        Malformed{R"({"start": [0, 0], "segments": [], "uav": 1})",
                  R"(bad.json: unknown key "uav" (expected "start" and "segments"))"},
        Malformed{R"({"start": [0], "segments": []})", "bad.json: start: expected [x, y] integers"},
        Malformed{R"({"start": [0.5, 1], "segments": []})",
                  "bad.json: start: expected [x, y] integers"},
        Malformed{R"({"start": ["0", 1], "segments": []})",
                  "bad.json: start: expected [x, y] integers"},
        Malformed{R"({"start": [0, 0], "segments": {}})",
                  "bad.json: segments: expected an array of [[x1, y1], [x2, y2]]"},
        Malformed{R"({"start": [0, 0], "segments": [[[0, 0], [1, 0]], [[0, 0]]]})",
                  "bad.json: segments[1]: expected [[x1, y1], [x2, y2]]"},
        Malformed{R"({"start": [0, 0], "segments": [[[0, 0], [1, 0]], [[0, 0], [1, 0]],
                      [[0, 0], [1, 0]], [[0, 0], [1, 0, 2]]]})",
                  "bad.json: segments[3][1]: expected [x, y] integers"},
        Malformed{R"({"start": [0, 0], "segments": [[[2000000, 0], [1, 0]]]})",
                  "bad.json: segments[0][0]: coordinate 2000000 is outside [-1000000, 1000000]"},
        Malformed{R"({"start": [0, 0], "segments": [[[0, 0], [1, -1000001]]]})",
                  "bad.json: segments[0][1]: coordinate -1000001 is outside [-1000000, 1000000]"},
        Malformed{R"({"start": [0, -18446744073709551615], "segments": []})",
                  "bad.json: start: expected [x, y] integers"},
        Malformed{
            R"({"start": [0, 18446744073709551615], "segments": []})",
            "bad.json: start: coordinate 18446744073709551615 is outside [-1000000, 1000000]"}));

TEST(TspInstanceJson, SyntaxErrorsAndMissingFiles) {
  try {
    parse_tsp_instance("{\"start\": [0, 0],\n \"segments\": [}", "syntax.json");
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_EQ(what.rfind("syntax.json:2: not valid JSON: syntax error while parsing value", 0), 0u)
        << what;
  }
  try {
    read_tsp_instance("/nonexistent/instance.json");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/instance.json: cannot open the file");
  }
}

TEST(TspSolutionJson, FieldsInTheDocumentedOrder) {
  tsp::TspSolution s;
  s.order = {{2, true}, {0, false}};
  s.length = 17;
  s.optimal = true;
  s.lower_bound = 17;
  s.seconds = 0.25;
  EXPECT_EQ(
      tsp_solution_json(s).dump(),
      R"({"length":17,"optimal":true,"lower_bound":17,"order":[{"segment":2,"reversed":true},)"
      R"({"segment":0,"reversed":false}],"seconds":0.25})");
}

}  // namespace
}  // namespace hullinspect::io
