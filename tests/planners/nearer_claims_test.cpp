// Sweep-Inspect's claims: a claim holds only against UAVs no nearer to the cell than its claimer.

#include "hullinspect/planners/nearer_claims.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace hullinspect::planners {
namespace {

struct Fleet {
  std::vector<int> claims;     // per UAV: its claimed cell, or -1
  std::vector<int> distances;  // per UAV: its flight to the cell asked about
  int asked_for_k = 0;         // how often UAV k's distance was asked

  bool held_against(int k, int cell) {
    asked_for_k = 0;
    return claim_held_against(
        static_cast<int>(claims.size()), k, cell,
        [&](int j) { return claims[static_cast<std::size_t>(j)]; },
        [&](int j) {
          if (j == k) ++asked_for_k;
          return distances[static_cast<std::size_t>(j)];
        });
  }
};

TEST(NearerClaims, AClaimHoldsAgainstUavsNoNearer) {
  Fleet fleet{{7, -1, -1}, {5, 5, 9}};
  EXPECT_TRUE(fleet.held_against(1, 7));  // as near as the claimer: held
  EXPECT_TRUE(fleet.held_against(2, 7));  // farther: held
  fleet.distances = {5, 4, 9};
  EXPECT_FALSE(fleet.held_against(1, 7));  // nearer: UAV 1 may take it
}

TEST(NearerClaims, OwnClaimsOtherCellsAndNoCellAreNotHeld) {
  Fleet fleet{{7, 3, -1}, {1, 1, 1}};
  EXPECT_FALSE(fleet.held_against(0, 7));  // its own claim
  EXPECT_FALSE(fleet.held_against(2, 8));  // nobody claims cell 8
  EXPECT_FALSE(fleet.held_against(2, -1));
  EXPECT_EQ(fleet.asked_for_k, 0);  // no claim on the cell: no distance asked
}

TEST(NearerClaims, AnyNearEnoughClaimerHoldsIt) {
  // Two claimers of one cell: the far one does not hold it against UAV 2, the near one does.
  Fleet fleet{{4, 4, -1}, {20, 2, 6}};
  EXPECT_TRUE(fleet.held_against(2, 4));
  EXPECT_EQ(fleet.asked_for_k, 1);  // UAV 2's own flight asked once
  fleet.distances = {20, 8, 6};
  EXPECT_FALSE(fleet.held_against(2, 4));
}

}  // namespace
}  // namespace hullinspect::planners
