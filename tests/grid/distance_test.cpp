#include "hullinspect/grid/distance.hpp"

#include <gtest/gtest.h>

namespace hullinspect::grid {
namespace {

Grid<std::uint8_t> mask_from(const std::vector<std::string>& rows_top_first) {
  const int h = static_cast<int>(rows_top_first.size());
  const int w = static_cast<int>(rows_top_first[0].size());
  Grid<std::uint8_t> m(w, h, 0);
  for (int r = 0; r < h; ++r) {
    for (int x = 0; x < w; ++x) m(x, h - 1 - r) = rows_top_first[static_cast<std::size_t>(r)][x] == 'X';
  }
  return m;
}

TEST(BfsDistances, GoesAroundObstacles) {
  const auto m = mask_from({"XXXXX",
                            "X.X.X",
                            "X.X.X",
                            "XXX.X"});
  Grid<int> d;
  BfsScratch scratch;
  const int source = m.index(0, 0);
  bfs_distances(m, std::span<const int>(&source, 1), d, scratch);
  EXPECT_EQ(d(0, 0), 0);
  EXPECT_EQ(d(2, 0), 2);
  EXPECT_EQ(d(2, 2), 4);
  EXPECT_EQ(d(4, 0), 10);  // up the left side, along the top, down the right side
  EXPECT_EQ(d(1, 1), kUnreachable);
  EXPECT_EQ(d(3, 0), kUnreachable);
}

TEST(BfsDistances, MultipleSourcesTakeTheNearest) {
  const auto m = mask_from({"XXXXXXX"});
  Grid<int> d;
  BfsScratch scratch;
  const std::vector<int> sources = {0, 6};
  bfs_distances(m, sources, d, scratch);
  EXPECT_EQ((std::vector<int>(d.values().begin(), d.values().end())),
            (std::vector<int>{0, 1, 2, 3, 2, 1, 0}));
}

TEST(LabelComponents, CountsFourConnectedPiecesInYXOrder) {
  const auto m = mask_from({"X.X",
                            ".X.",
                            "XX."});
  Grid<int> labels;
  BfsScratch scratch;
  EXPECT_EQ(label_components(m, labels, scratch), 3);  // diagonal contact does not connect
  EXPECT_EQ(labels(0, 0), 0);
  EXPECT_EQ(labels(1, 0), 0);
  EXPECT_EQ(labels(1, 1), 0);
  EXPECT_EQ(labels(0, 2), 1);
  EXPECT_EQ(labels(2, 2), 2);
  EXPECT_EQ(labels(2, 0), -1);
}

// A seam table linking every row's two ends (one step each; only the links matter here).
EdgeSteps seam_of(int width, int height) {
  EdgeSteps links;
  links.east = Grid<std::uint8_t>(width, height, 1);
  links.north = Grid<std::uint8_t>(width, height, 1);
  links.seam.assign(static_cast<std::size_t>(height), 1);
  return links;
}

TEST(BfsDistances, StepsAcrossTheSeamOfAGridThatClosesOnItself) {
  // (4, 1) is one step from (0, 1) across the seam, six round through the bottom row without it;
  // (2, 1) is no position to fly.
  const auto m = mask_from({"XX.XX", "XXXXX"});
  Grid<int> d;
  BfsScratch scratch;
  const int source = m.index(0, 1);
  bfs_distances(m, std::span<const int>(&source, 1), d, scratch, seam_of(5, 2));
  EXPECT_EQ(d(4, 1), 1);
  EXPECT_EQ(d(3, 1), 2);
  EXPECT_EQ(d(4, 0), 2);
  EXPECT_EQ(d(2, 1), kUnreachable);
  bfs_distances(m, std::span<const int>(&source, 1), d, scratch, EdgeSteps{});
  EXPECT_EQ(d(4, 1), 6);
  EXPECT_EQ(d(3, 1), 5);
}

TEST(LabelComponents, JoinsPiecesThatMeetAcrossTheSeam) {
  const auto m = mask_from({"X...X", "X.X.X"});
  Grid<int> labels;
  BfsScratch scratch;
  EXPECT_EQ(label_components(m, labels, scratch), 3);
  EXPECT_EQ(label_components(m, labels, scratch, seam_of(5, 2)), 2);
  EXPECT_EQ(labels(0, 0), labels(4, 1));
  EXPECT_NE(labels(2, 0), labels(0, 0));
  // One linked row joins the two ends; a row the seam does not link keeps its ends apart.
  EdgeSteps top_only = seam_of(5, 2);
  top_only.seam[0] = 0;
  EXPECT_EQ(label_components(m, labels, scratch, top_only), 2);
  top_only.seam[1] = 0;
  EXPECT_EQ(label_components(m, labels, scratch, top_only), 3);
}

TEST(Cell, OrdersByYThenX) {
  EXPECT_LT((Cell{5, 0}), (Cell{0, 1}));
  EXPECT_LT((Cell{0, 1}), (Cell{1, 1}));
  EXPECT_EQ(manhattan({1, 2}, {4, 0}), 5);
}

}  // namespace
}  // namespace hullinspect::grid
