// The step loop allocates nothing: count global operator new calls across simulator steps and a
// whole lawnmower mission's decide/step loop after start-up.

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "hullinspect/planners/lawnmower_planner.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/sim/simulator.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }

namespace hullinspect::sim {
namespace {

TEST(Allocation, CounterSeesAllocations) {
  const long before = g_allocations.load();
  auto* p = new std::vector<int>(100);
  delete p;
  EXPECT_EQ(g_allocations.load() - before, 2);  // the vector object and its buffer
}

TEST(Allocation, StepLoopAllocatesNothing) {
  const auto& hull = world::default_hull();
  const auto instance = world::generate_instance(hull, world::CorrosionParams::homogeneous(230, 0.01, 5, 0.6, 0.003), 4);
  world::MissionParams params;
  params.uavs = 8;
  params.s2 = 11;
  planners::DirectPartitionSource partitions;
  const auto starts = world::start_cells(params, hull);
  planners::PlannerContext context{hull, params, instance.prior, starts, partitions};
  planners::LawnmowerPlanner planner({});
  planner.start(context);
  Simulator sim(hull, instance, params);
  std::vector<Action> actions(8, Action::kHover);
  // One step to let lazily sized planner buffers settle, then count.
  planner.decide(sim.view(), actions);
  sim.step(actions);
  const long before = g_allocations.load();
  int steps = 0;
  while (!sim.finished()) {
    std::fill(actions.begin(), actions.end(), Action::kHover);
    planner.decide(sim.view(), actions);
    sim.step(actions);
    ++steps;
  }
  EXPECT_TRUE(sim.complete());
  EXPECT_GT(steps, 100);
  EXPECT_EQ(g_allocations.load() - before, 0) << "allocations during " << steps << " steps";
}

}  // namespace
}  // namespace hullinspect::sim
