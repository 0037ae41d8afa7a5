// --geo files (docs/export.md "Geo-referencing"): two surveyed points given as grid cells put the
// waypoints where the origin and heading they were surveyed from put them.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/io/geo_reference.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

const io::GeoReference kReference({53.5461, 9.9665, 3.0}, 117.0);

// The hull's surface at the centre of cell (col, row), from the trace's own numbers: the grid's
// origin, the side plane and the cell's depth toward the inspected side (docs/trace-format.md).
std::array<double, 3> surface_point(const nlohmann::json& trace, int col, int row) {
  const double cell = trace["grid"]["cell_size_m"].get<double>();
  const auto& frame = trace["ship_frame"];
  const double sign = frame["side"] == "port" ? 1.0 : -1.0;
  return {frame["origin"][0].get<double>() + (col + 0.5) * cell,
          frame["side_plane_y"].get<double>() + sign * frame["depth"][row][col].get<double>(),
          frame["origin"][1].get<double>() + (row + 0.5) * cell};
}

std::string at(const std::array<double, 3>& p) {
  const auto g = kReference.to_wgs84(p[0], p[1], p[2]);
  return fmt::format("[{:.12f}, {:.12f}, {:.6f}]", g.lat, g.lon, g.alt);
}

// Rows of an export's CSV after its header.
std::vector<std::vector<std::string>> csv_rows(const std::string& path) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(io::read_file(path));
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ',')) row.push_back(f);
    rows.push_back(row);
  }
  return rows;
}

TEST(GeoFile, SurveyedCellsGiveTheWaypointsOfTheirOriginAndHeading) {
  const auto dir = make_temp_dir("geo-cells");
  const auto stl = wigley_stl({40, 6, 4, 80, 16, false});
  const auto trace_path = dir + "/trace.json";
  const auto planned = run_cli({"plan", "--hull", stl.string(), "-n", "1", "--trace", trace_path});
  ASSERT_EQ(planned.status, 0) << planned.err;
  const auto trace = nlohmann::json::parse(io::read_file(trace_path));
  ASSERT_TRUE(trace.contains("ship_frame"));
  // Stern and bow cells near the waterline (row 6 of 8), on a curved side: depth differs.
  const int row = 6;
  const int stern = 6, bow = 70;
  ASSERT_NE(trace["ship_frame"]["depth"][row][stern], trace["ship_frame"]["depth"][row][bow]);
  const auto a = surface_point(trace, stern, row);
  const auto b = surface_point(trace, bow, row);
  // Both points as cells, and one as a cell with the other in ship-frame metres.
  const std::string cells = fmt::format(
      "survey:\n  - {{cell: [{}, {}], at: {}}}\n  - {{cell: [{}, {}], at: {}}}\ntolerance: 0.05\n",
      stern, row, at(a), bow, row, at(b));
  const std::string mixed =
      fmt::format("survey:\n  - {{cell: [{}, {}], at: {}}}\n  - {{ship: [{}, {}, {}], at: {}}}\n",
                  stern, row, at(a), b[0], b[1], b[2], at(b));
  std::ofstream(dir + "/cells.yaml") << cells;
  std::ofstream(dir + "/mixed.yaml") << mixed;
  const auto reference = run_cli({"export", trace_path, "--format", "csv", "--origin",
                                  "53.5461,9.9665,3", "--heading", "117", "--out", dir + "/ref"});
  ASSERT_EQ(reference.status, 0) << reference.err;
  const auto expected = csv_rows(dir + "/ref/uav0.csv");
  ASSERT_GT(expected.size(), 10u);
  for (const char* geo : {"cells.yaml", "mixed.yaml"}) {
    const auto out = dir + "/" + std::string(geo) + ".out";
    const auto r =
        run_cli({"export", trace_path, "--format", "csv", "--geo", dir + "/" + geo, "--out", out});
    ASSERT_EQ(r.status, 0) << geo << ": " << r.err;
    const auto got = csv_rows(out + "/uav0.csv");
    ASSERT_EQ(got.size(), expected.size()) << geo;
    const auto lat = got.front().size() - 4, lon = lat + 1, alt = lat + 2;
    for (std::size_t i = 0; i < got.size(); ++i) {
      // 1e-9° is about 0.1 mm: the survey recovers the reference to well below a centimetre.
      EXPECT_NEAR(std::stod(got[i][lat]), std::stod(expected[i][lat]), 1e-9) << geo << " " << i;
      EXPECT_NEAR(std::stod(got[i][lon]), std::stod(expected[i][lon]), 1e-9) << geo << " " << i;
      EXPECT_NEAR(std::stod(got[i][alt]), std::stod(expected[i][alt]), 1e-3) << geo << " " << i;
    }
  }
  // A surveyed cell off the hull is refused, naming the file, its line and the cell.
  std::ofstream(dir + "/off.yaml")
      << fmt::format("survey:\n  - {{cell: [{}, {}], at: {}}}\n  - {{cell: [500, {}], at: {}}}\n",
                     stern, row, at(a), row, at(b));
  const auto off = run_cli(
      {"export", trace_path, "--format", "csv", "--geo", dir + "/off.yaml", "--out", dir + "/off"});
  EXPECT_EQ(off.status, 2);
  EXPECT_NE(off.err.find("off.yaml:3: survey[1].cell: (500, 6) is not a hull cell"),
            std::string::npos)
      << off.err;
  EXPECT_FALSE(fs::exists(dir + "/off/uav0.csv"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
