#include "hullinspect/world/hull.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::world {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(DefaultHull, IsTheDocumentedShipProfile) {
  const HullMask& h = default_hull();
  EXPECT_EQ(h.width(), 230);
  EXPECT_EQ(h.height(), 30);
  EXPECT_EQ(h.cell_count(), 6361);
  // Keel line along the bottom of the midbody, deck line along the top.
  for (int x = 24; x <= 196; ++x) EXPECT_TRUE(h.is_hull(x, 0)) << x;
  for (int x = 0; x < 230; ++x) EXPECT_TRUE(h.is_hull(x, 29)) << x;
  // Stern overhang: the stern's bottom is cut away; raked bow: the stem's foot is aft of its head.
  EXPECT_FALSE(h.is_hull(0, 0));
  EXPECT_FALSE(h.is_hull(0, 13));
  EXPECT_TRUE(h.is_hull(0, 14));
  EXPECT_FALSE(h.is_hull(229, 0));
  EXPECT_TRUE(h.is_hull(229, 29));
  EXPECT_EQ(h.source(), "builtin:default");
}

TEST(TextMask, ParsesTopRowFirstWithComments) {
  const HullMask h = parse_text_mask("; a comment\nXX.\nXXX\n", "t.txt");
  EXPECT_EQ(h.width(), 3);
  EXPECT_EQ(h.height(), 2);
  EXPECT_TRUE(h.is_hull(0, 1));
  EXPECT_FALSE(h.is_hull(2, 1));
  EXPECT_TRUE(h.is_hull(2, 0));
  EXPECT_EQ(to_text_mask(h), "XX.\nXXX\n");
}

TEST(TextMask, RejectsBadInputNamingFileAndLine) {
  EXPECT_EQ(error_of([] { parse_text_mask("XX\nX?\n", "h.txt"); }),
            "h.txt:2: unexpected character '?' in column 2; a text mask uses 'X' or '#' (hull) and "
            "'.' (not hull)");
  EXPECT_EQ(error_of([] { parse_text_mask("XXX\nXX\n", "h.txt"); }),
            "h.txt:2: row has 2 cells but the first row has 3");
  EXPECT_EQ(error_of([] { parse_text_mask("; only a comment\n", "h.txt"); }),
            "h.txt: no mask rows (the file is empty)");
  EXPECT_EQ(error_of([] { parse_text_mask("...\n...\n", "h.txt"); }),
            "h.txt: the hull is empty (no hull cells)");
  EXPECT_EQ(error_of([] { parse_text_mask("X.X\nX.X\n", "h.txt"); }),
            "h.txt: the hull is not 4-connected: 2 components (2 cells from (0, 0); 2 cells from (2, 0))");
  EXPECT_EQ(error_of([] { parse_text_mask(std::string(5000, 'X') + "\n", "h.txt"); }),
            "h.txt:1: row has 5000 cells; at most 4096 are accepted");
}

TEST(PgmMask, ReadsAsciiAndBinary) {
  const HullMask a = parse_pgm_mask("P2\n# comment\n3 2\n255\n255 255 0\n255 255 255\n", "a.pgm");
  EXPECT_EQ(a.cell_count(), 5);
  EXPECT_FALSE(a.is_hull(2, 1));  // first image row is the top
  std::string bin = "P5 3 2 255\n";
  bin += std::string("\xff\xff\x00\xff\xff\xff", 6);
  const HullMask b = parse_pgm_mask(bin, "b.pgm");
  EXPECT_EQ(b.mask(), a.mask());
}

TEST(PgmMask, RejectsMalformedImages) {
  EXPECT_EQ(error_of([] { parse_pgm_mask("P3\n", "x.pgm"); }),
            "x.pgm:1: not a greyscale PGM image (magic 'P3'; expected 'P2' or 'P5')");
  EXPECT_EQ(error_of([] { parse_pgm_mask("P2\n3 x\n", "x.pgm"); }),
            "x.pgm:2: expected the image height (a non-negative integer)");
  EXPECT_EQ(error_of([] { parse_pgm_mask("P2\n2 1\n255\n255 300\n", "x.pgm"); }),
            "x.pgm:4: grey value 300 exceeds the maximum 255");
  EXPECT_EQ(error_of([] { parse_pgm_mask("P5\n2 2\n255\n\xff", "x.pgm"); }),
            "x.pgm:4: pixel data is truncated: 1 bytes for 4 pixels");
  EXPECT_EQ(error_of([] { parse_pgm_mask("P2\n0 5\n255\n", "x.pgm"); }),
            "x.pgm:3: image is 0 × 5; each side must be within 1..4096");
}

TEST(LoadHull, ReadsFilesByContentAndReportsMissingFiles) {
  const auto dir = std::filesystem::temp_directory_path();
  const auto text = dir / "hullinspect_load_test.txt";
  std::ofstream(text) << "XX\nXX\n";
  EXPECT_EQ(load_hull(text).cell_count(), 4);
  const auto pgm = dir / "hullinspect_load_test.pgm";
  std::ofstream(pgm) << "P2 2 1 1\n1 1\n";
  EXPECT_EQ(load_hull(pgm).cell_count(), 2);
  EXPECT_EQ(load_hull("default").cell_count(), 6361);
  EXPECT_EQ(error_of([] { load_hull("/nonexistent/hull.txt"); }),
            "/nonexistent/hull.txt: cannot open the hull file");
  std::filesystem::remove(text);
  std::filesystem::remove(pgm);
}

TEST(Snap, PicksNearestHullCellLowestYThenX) {
  const HullMask h = parse_text_mask("X...X\nX...X\nXXXXX\n", "s");
  EXPECT_EQ(h.snap({2, 0}), (grid::Cell{2, 0}));
  EXPECT_EQ(h.snap({2, 2}), (grid::Cell{2, 0}));  // distance 2 to (2,0), (0,2) and (4,2): lowest y
  EXPECT_EQ(h.snap({1, 2}), (grid::Cell{0, 2}));
}

}  // namespace
}  // namespace hullinspect::world
