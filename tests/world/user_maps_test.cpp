#include "hullinspect/world/user_maps.hpp"

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

class UserMapFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hullinspect_maps_" + std::to_string(::getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return (dir_ / name).string();
  }
  fs::path dir_;
  // 4 × 3, top row first: the top-right cell is not hull.
  HullMask hull_ = parse_text_mask("XXX.\nXXXX\nXXXX\n", "hull.txt");
};

TEST_F(UserMapFiles, MarkedCellsAreCorroded) {
  const std::string truth = write("truth.txt", "X...\n....\n...X\n");
  const CorrosionMap m = load_corrosion_map(truth, hull_);
  EXPECT_EQ(m.cells(0, 2), 1);
  EXPECT_EQ(m.cells(3, 0), 1);
  EXPECT_EQ(m.cells(1, 1), 0);
  EXPECT_EQ(m.cells(3, 2), -1);  // not hull
  // PGM works too (first image row is the top).
  const std::string pgm = write("prior.pgm", "P2\n4 3\n1\n0 0 0 0\n0 1 0 0\n0 0 0 0\n");
  const UserMaps maps = load_user_maps(pgm, truth, hull_);
  Instance instance = generate_instance(hull_, CorrosionParams::homogeneous(4, 0.5, 1), 3);
  apply(maps, instance);
  EXPECT_EQ(instance.truth, m.cells);
  EXPECT_EQ(instance.prior(1, 1), 1);
  EXPECT_EQ(instance.corroded_cells(), 2);
  EXPECT_EQ(instance.truth_centres, 0);
  // Only the prior: the generated truth stays.
  Instance generated = generate_instance(hull_, CorrosionParams::homogeneous(4, 0.5, 1), 3);
  Instance only_prior = generated;
  apply(load_user_maps(pgm, "", hull_), only_prior);
  EXPECT_EQ(only_prior.truth, generated.truth);
  EXPECT_EQ(only_prior.prior, maps.prior->cells);
}

TEST_F(UserMapFiles, MismatchesNameTheFileAndCell) {
  const std::string wide = write("wide.txt", "X....\n.....\n.....\n");
  EXPECT_EQ(error_of([&] { load_corrosion_map(wide, hull_); }),
            wide + ": the map is 5 × 3 but the hull (hull.txt) is 4 × 3");
  const std::string outside = write("outside.txt", "...X\n....\n....\n");
  EXPECT_EQ(error_of([&] { load_corrosion_map(outside, hull_); }),
            outside + ": cell (3, 2) is corroded but not part of the hull");
  const std::string bad = write("bad.txt", "..a.\n....\n....\n");
  EXPECT_EQ(error_of([&] { load_corrosion_map(bad, hull_); }),
            bad +
                ":1: unexpected character 'a' in column 3; a text mask uses 'X' or '#' (hull) "
                "and '.' (not hull)");
  EXPECT_EQ(error_of([&] { load_corrosion_map(dir_ / "missing.txt", hull_); }),
            (dir_ / "missing.txt").string() + ": cannot open the file");
  // An empty map (no corrosion) is fine.
  EXPECT_EQ(load_corrosion_map(write("clean.txt", "....\n....\n....\n"), hull_).cells(0, 0), 0);
}

}  // namespace
}  // namespace hullinspect::world
