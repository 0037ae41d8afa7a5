// The mission partition's DARP → transfer fallback (partition/fallback.hpp, docs/model.md): DARP's
// own partition wherever it converges, the transfer partitioner's when it does not, and no fallback
// for any other partitioner.

#include "hullinspect/partition/fallback.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "hullinspect/world/mission_params.hpp"
#include "support/partition_checker.hpp"

namespace hullinspect::partition {
namespace {

PartitionRequest default_request(int n) {
  world::MissionParams params;
  params.uavs = n;
  PartitionRequest request;
  request.hull = &world::default_hull();
  request.starts = world::start_cells(params, *request.hull);
  return request;
}

// One DARP iteration at tolerance 0: DARP cannot converge and returns its best connected iterate.
const OptionMap kStarvedDarp = {{"iteration-limit", "1"}, {"max-discrepancy", "0"}};

TEST(PartitionFallback, ConvergedDarpIsReturnedUnchanged) {
  const PartitionRequest request = default_request(4);
  const Partition darp = make_partitioner("darp")->partition(request);
  ASSERT_TRUE(darp.converged);
  const Partition used = partition_with_fallback("darp", {}, request);
  EXPECT_TRUE(used.fallback.empty());
  EXPECT_TRUE(std::ranges::equal(used.owner.values(), darp.owner.values()));
  EXPECT_EQ(used.iterations, darp.iterations);
  EXPECT_EQ(used.warnings, darp.warnings);
}

TEST(PartitionFallback, DarpThatDoesNotConvergeFallsBackToTransfer) {
  const PartitionRequest request = default_request(8);
  const Partition darp = make_partitioner("darp", kStarvedDarp)->partition(request);
  ASSERT_FALSE(darp.converged);
  const Partition used = partition_with_fallback("darp", kStarvedDarp, request);
  EXPECT_EQ(used.fallback, "transfer");
  EXPECT_TRUE(used.converged);
  EXPECT_TRUE(testing::valid_partition(request, used, {.tolerance = 1.0}));
  const Partition transfer = make_partitioner("transfer")->partition(request);
  EXPECT_TRUE(std::ranges::equal(used.owner.values(), transfer.owner.values()));
  ASSERT_FALSE(used.warnings.empty());
  EXPECT_EQ(used.warnings.front(), darp.warnings.front());
  EXPECT_NE(used.warnings.back().find("darp did not converge (largest imbalance "),
            std::string::npos)
      << used.warnings.back();
  EXPECT_NE(used.warnings.back().find("uses the transfer partitioner's partition (converged"),
            std::string::npos)
      << used.warnings.back();
}

TEST(PartitionFallback, OtherPartitionersNeverFallBack) {
  const PartitionRequest request = default_request(12);
  const Partition used = partition_with_fallback("transfer", {{"round-limit", "1"}}, request);
  EXPECT_FALSE(used.converged);
  EXPECT_TRUE(used.fallback.empty());
}

}  // namespace
}  // namespace hullinspect::partition
