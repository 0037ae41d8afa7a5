// DARP allocates nothing per iteration: a run of 40 iterations and one of 1200 make exactly the
// same number of heap allocations (counted by replacing the global operator new in this test
// program).

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "hullinspect/partition/darp_partitioner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mission_params.hpp"

namespace {
std::atomic<bool> g_counting{false};
std::atomic<long> g_allocations{0};

void* counted_allocation(std::size_t size) {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t size) {
  return counted_allocation(size);
}
void* operator new[](std::size_t size) {
  return counted_allocation(size);
}
// The nothrow forms too (std::stable_sort's temporary buffer uses them): every allocation of
// this program must come from malloc, since every delete below frees with free().
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  return std::malloc(size == 0 ? 1 : size);
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
  if (g_counting.load(std::memory_order_relaxed)) g_allocations.fetch_add(1);
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace hullinspect {
namespace {

struct Counted {
  long allocations;
  int iterations;
  bool converged;
};

Counted count_allocations(const partition::PartitionRequest& request, int iteration_limit) {
  partition::DarpOptions o;
  o.iteration_limit = iteration_limit;
  const partition::DarpPartitioner darp(o);
  g_allocations = 0;
  g_counting = true;
  const partition::Partition p = darp.partition(request);
  g_counting = false;
  return {g_allocations.load(), p.iterations, p.converged};
}

TEST(DarpAllocation, NoneInsideTheIterationLoop) {
  // A UAV walled into a dead end: DARP can never converge, so both runs use every iteration they
  // are given (and both end in the fallback, which allocates the same either way).
  const auto hull = world::parse_text_mask(
      "XXXXXXXXXXXXXXXXXXXX\n"
      "XXXXXXXXXXXXXXXXXXXX\n"
      "XXXXXXXXXXXXXXXXXXXX\n"
      "XXXXXXXXXXXXXXXXXXXX\n"
      "X...................\n",
      "walled");
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = {{0, 1}, {0, 0}, {10, 2}, {17, 3}};
  const Counted short_run = count_allocations(request, 20);
  const Counted long_run = count_allocations(request, 800);
  EXPECT_FALSE(short_run.converged);
  EXPECT_FALSE(long_run.converged);
  EXPECT_EQ(short_run.iterations, 20 + 10);
  EXPECT_EQ(long_run.iterations, 800 + 400);
  EXPECT_GT(short_run.allocations, 0);  // the counter works
  EXPECT_EQ(short_run.allocations, long_run.allocations);
}

TEST(DarpAllocation, ConvergingRunAllocatesNoMoreThanOneIteration) {
  // Eight UAVs on the default hull converge after about two hundred iterations, yet allocate no
  // more than a run stopped after one iteration (which also builds its fallback and warning).
  const auto& hull = world::default_hull();
  world::MissionParams params;
  params.uavs = 8;
  partition::PartitionRequest request;
  request.hull = &hull;
  request.starts = world::start_cells(params, hull);
  const Counted converging = count_allocations(request, 2000);
  const Counted stopped = count_allocations(request, 1);
  EXPECT_TRUE(converging.converged);
  EXPECT_GT(converging.iterations, 50);
  EXPECT_FALSE(stopped.converged);
  EXPECT_LE(converging.allocations, stopped.allocations);
}

}  // namespace
}  // namespace hullinspect
