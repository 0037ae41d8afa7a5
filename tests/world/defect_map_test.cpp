#include "hullinspect/world/defect_map.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <functional>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::world {
namespace {

namespace fs = std::filesystem;

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

// The corroded cells of a map as (x, y), row by row from y = 0.
std::vector<std::pair<int, int>> corroded(const CorrosionMap& m) {
  std::vector<std::pair<int, int>> cells;
  for (int y = 0; y < m.cells.height(); ++y) {
    for (int x = 0; x < m.cells.width(); ++x) {
      if (m.cells(x, y) == 1) cells.emplace_back(x, y);
    }
  }
  return cells;
}

class DefectFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hullinspect_defects_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
  // 8 × 4 cells of 0.5 m (a mask: origin at its bottom-left corner, starboard); top row first,
  // the top-right two cells are not hull.
  HullMask hull_ = parse_text_mask("XXXXXX..\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n", "plate.txt");
};

TEST_F(DefectFiles, ARectangleMarksTheCellsWhoseCentreItHolds) {
  // Centred at (1.0, 0.5) m, 1 m × 0.5 m: x ∈ [0.5, 1.5) holds the column centres 0.75 and 1.25
  // (columns 1, 2); z ∈ [0.25, 0.75) holds the row centre 0.25 (row 0) but not 0.75.
  const auto path = write("d.csv", "x_m,z_m,side,w_m,h_m\n1.0,0.5,starboard,1.0,0.5\n");
  const CorrosionMap m = load_defect_map(path, hull_, {});
  EXPECT_EQ(corroded(m), (std::vector<std::pair<int, int>>{{1, 0}, {2, 0}}));
  EXPECT_EQ(m.cells(0, 0), 0);
  EXPECT_EQ(m.cells(7, 3), -1);  // not hull
  EXPECT_EQ(m.source, path);
}

TEST_F(DefectFiles, ColumnsMayComeInAnyOrderWithCommentsAndSpaces) {
  const auto a = write("a.csv", "x_m,z_m,side,w_m,h_m\n2.0,1.0,starboard,0.6,0.6\n");
  const auto b = write(
      "b.csv", "# survey of 2026\nside, h_m, w_m, z_m, x_m\n\n starboard , 0.6,0.6,1.0,2.0\r\n");
  EXPECT_EQ(corroded(load_defect_map(a, hull_, {})), corroded(load_defect_map(b, hull_, {})));
  EXPECT_EQ(corroded(load_defect_map(a, hull_, {})),
            (std::vector<std::pair<int, int>>{{3, 1}, {4, 1}, {3, 2}, {4, 2}}));
}

TEST_F(DefectFiles, FrameNumbersUseTheFrameSpacing) {
  const auto by_metres = write("m.csv", "x_m,z_m,side,w_m,h_m\n2.4,1.0,starboard,1,1\n");
  const auto by_frame = write("f.csv", "frame,z_m,side,w_m,h_m\n3,1.0,starboard,1,1\n");
  FrameSpacing frames;
  frames.frame_spacing_m = 0.8;
  EXPECT_EQ(corroded(load_defect_map(by_frame, hull_, frames)),
            corroded(load_defect_map(by_metres, hull_, {})));
  EXPECT_EQ(error_of([&] { load_defect_map(by_frame, hull_, {}); }),
            by_frame + ":2: frame: a frame number needs the frame spacing (--frame-spacing)");
}

TEST_F(DefectFiles, ADefectSmallerThanACellMarksTheCellHoldingItsCentre) {
  // 10 cm pitting at (1.6, 1.1) m: no cell centre inside; the cell holding it is (3, 2).
  const auto path = write("pit.csv", "x_m,z_m,side,w_m,h_m\n1.6,1.1,starboard,0.1,0.1\n");
  EXPECT_EQ(corroded(load_defect_map(path, hull_, {})), (std::vector<std::pair<int, int>>{{3, 2}}));
}

TEST_F(DefectFiles, JsonGivesTheSameMapAsCsv) {
  const auto csv = write("d.csv",
                         "x_m,z_m,side,w_m,h_m\n1.0,0.5,starboard,1.0,0.5\n"
                         "3.0,1.5,starboard,0.5,1.0\n");
  const auto json = write("d.json",
                          R"({"defects": [{"x_m": 1.0, "z_m": 0.5, "side": "starboard", "w_m": 1.0,
                           "h_m": 0.5}, {"x_m": 3.0, "z_m": 1.5, "side": "starboard",
                           "w_m": 0.5, "h_m": 1.0}]})");
  EXPECT_EQ(corroded(load_defect_map(json, hull_, {})), corroded(load_defect_map(csv, hull_, {})));
  EXPECT_EQ(corroded(load_defect_map(csv, hull_, {})).size(), 4u);
}

TEST_F(DefectFiles, UsesTheHullGeometryOfAMeshHull) {
  // The same mask placed at x0 = 10 m, z0 = -1 m with 1 m cells, seen from port.
  HullMask hull = hull_;
  HullGeometry g;
  g.cell_size = 1.0;
  g.x0 = 10;
  g.z0 = -1;
  g.side = HullSide::port;
  g.depth = grid::Grid<float>(8, 4, 0.0f);
  g.coverage = grid::Grid<float>(8, 4, 1.0f);
  g.normal = grid::Grid<Normal>(8, 4, Normal{0, 1, 0});
  hull.attach_geometry(std::move(g));
  const auto path = write("d.csv", "x_m,z_m,side,w_m,h_m\n12.5,0.5,port,1,1\n");
  EXPECT_EQ(corroded(load_defect_map(path, hull, {})), (std::vector<std::pair<int, int>>{{2, 1}}));
  const auto starboard = write("s.csv", "x_m,z_m,side,w_m,h_m\n12.5,0.5,starboard,1,1\n");
  EXPECT_EQ(error_of([&] { load_defect_map(starboard, hull, {}); }),
            starboard + ":2: the defect is on the starboard side but the hull shows port");
}

TEST_F(DefectFiles, BadFilesNameTheLineOrDefect) {
  const auto check = [&](const std::string& name, const std::string& text,
                         const std::string& message) {
    const auto path = write(name, text);
    EXPECT_EQ(error_of([&] { load_defect_map(path, hull_, {}); }), path + message) << text;
  };
  const std::string header = "x_m,z_m,side,w_m,h_m\n";
  check("off.csv", header + "1.0,0.5,starboard,1,1\n40,0.5,starboard,1,1\n",
        ":3: the defect at x 40 m, z 0.5 m covers no hull cell (the grid spans x 0 … 4 m, z 0 … "
        "2 m)");
  check("notch.csv", header + "3.75,1.75,starboard,0.5,0.5\n",
        ":2: the defect at x 3.75 m, z 1.75 m covers no hull cell (the grid spans x 0 … 4 m, z 0 "
        "… 2 m)");
  check("port.csv", header + "1,1,port,1,1\n",
        ":2: the defect is on the port side but the hull shows starboard");
  check("side.csv", header + "1,1,bow,1,1\n", ":2: side: must be port or starboard (got 'bow')");
  check("unit.csv", "x_ft,z_m,side,w_m,h_m\n",
        ":1: header: unknown column 'x_ft' (expected x_m or frame, z_m, side, w_m, h_m)");
  check("both.csv", "x_m,frame,z_m,side,w_m,h_m\n",
        ":1: header: needs exactly one of x_m and frame");
  check("short.csv", "x_m,z_m,side,w_m\n", ":1: header: has no h_m");
  check("twice.csv", "x_m,z_m,side,w_m,h_m,w_m\n", ":1: header: column 'w_m' appears twice");
  check("fields.csv", header + "1,1,starboard,1\n",
        ":2: expected 5 fields (as the header) but found 4");
  check("nan.csv", header + "nan,1,starboard,1,1\n",
        ":2: x_m: must be a number in [-100000, 100000] (got 'nan')");
  check("size.csv", header + "1,1,starboard,0,1\n", ":2: w_m, h_m: a defect needs a positive size");
  check("empty.csv", "# nothing\n",
        ": no header: the first line names the columns (x_m or frame, z_m, side, w_m, h_m)");
  check("list.json", R"({"defects": {}})", R"(: expected an object with an array "defects")");
  check("key.json", R"({"defects": [{"x_m": 1, "z_m": 1, "side": "starboard", "w_m": 1}]})",
        ": defects[0]: has no h_m");
  check("type.json",
        R"({"defects": [{"x_m": [1], "z_m": 1, "side": "starboard", "w_m": 1, "h_m": 1}]})",
        ": defects[0].x_m: expected a number or a string");
  check("port.json", R"({"defects": [{"x_m": 1, "z_m": 1, "side": "port", "w_m": 1, "h_m": 1}]})",
        ": defects[0]: the defect is on the port side but the hull shows starboard");
}

}  // namespace
}  // namespace hullinspect::world
