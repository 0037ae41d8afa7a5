// Coop-Frontier allocates nothing per step: count global operator new calls across whole missions'
// decide/step loops after start-up (its own executable, because it replaces operator new).

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "hullinspect/planners/coop_frontier_planner.hpp"
#include "hullinspect/world/scenario.hpp"
#include "hullinspect/sim/simulator.hpp"

namespace {
std::atomic<long> g_allocations{0};
}

// Out of line, so that GCC does not inline free() into delete-expressions and then flag the
// malloc/free pair as mismatched with operator new (-Wmismatched-new-delete, sanitizer builds).
[[gnu::noinline]] void* operator new(std::size_t size) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
[[gnu::noinline]] void operator delete(void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace hullinspect::planners {
namespace {

TEST(CoopFrontierAllocation, CounterSeesAllocations) {
  const long before = g_allocations.load();
  // The volatile pointer makes the allocation observable, so the optimiser cannot elide it.
  std::vector<int>* volatile p = new std::vector<int>(100);
  delete p;
  EXPECT_EQ(g_allocations.load() - before, 2);
}

TEST(CoopFrontierAllocation, StepLoopAllocatesNothing) {
  const auto& hull = world::default_hull();
  for (const char* name : {"perfect", "combined"}) {
    for (int n : {1, 8}) {
      const auto instance =
          world::generate_instance(hull, world::scenario(name).corrosion(hull.width()), 4);
      world::MissionParams params;
      params.uavs = n;
      params.s2 = 11;
      DirectPartitionSource partitions;
      const auto starts = world::start_cells(params, hull);
      PlannerContext context{hull, params, instance.prior, starts, partitions};
      CoopFrontierPlanner planner;
      planner.start(context);
      sim::Simulator sim(hull, instance, params);
      std::vector<sim::Action> actions(static_cast<std::size_t>(n), sim::Action::kHover);
      const long before = g_allocations.load();
      int steps = 0;
      while (!sim.finished()) {
        std::fill(actions.begin(), actions.end(), sim::Action::kHover);
        planner.decide(sim.view(), actions);
        sim.step(actions);
        ++steps;
      }
      EXPECT_TRUE(sim.complete());
      EXPECT_GT(steps, 100);
      EXPECT_GT(planner.stats().assignments, 10);
      EXPECT_EQ(g_allocations.load() - before, 0)
          << name << " n = " << n << ": allocations during " << steps << " steps";
    }
  }
}

}  // namespace
}  // namespace hullinspect::planners
