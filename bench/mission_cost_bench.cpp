// CPU cost of a mission per planner on the paper preset's grid, with each planner's ratio to the
// lawnmower's, measured in one run: four scenarios × s2 ∈ {7, 9, 11} × n ∈ {4 … 8} × seeds, each
// planner with the preset's options (Part-TSP r1 = 2, r2 = 0) and one partition cache per planner
// as in an experiment (a partition is computed once per fleet size and shared by its missions).
// Times are CPU time of this thread, so the other load on the machine does not count.
//
//   build/release/bench/mission_cost_bench                  # n = 4 … 8, seeds 1-3
//   build/release/bench/mission_cost_bench --seeds 10 --uavs 4,8
//   build/release/bench/mission_cost_bench --algorithms lawnmower,part-tsp,sweep-inspect
//
// Columns: missions, CPU ms per mission (mean, median), ratio of the mean to the lawnmower's, and
// the missions that did not complete.

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/partition_cache.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/scenario.hpp"
#include "paper_grid_mission.hpp"

#include "bench_support.hpp"

namespace {

using namespace hullinspect;

using bench::thread_cpu_seconds;

std::vector<std::string> split(const std::string& text) {
  return bench::split(text, ',');
}

struct Options {
  std::vector<std::string> algorithms{"lawnmower", "part-tsp", "part-tsp0", "coop-frontier"};
  std::vector<int> uavs{4, 5, 6, 7, 8};
  int seeds = 3;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) throw std::invalid_argument(fmt::format("{}: expected a value", arg));
    const std::string value = argv[++i];
    try {
      if (arg == "--algorithms") {
        o.algorithms = split(value);
      } else if (arg == "--uavs") {
        o.uavs.clear();
        for (const auto& n : split(value)) o.uavs.push_back(std::stoi(n));
      } else if (arg == "--seeds") {
        o.seeds = std::stoi(value);
      } else {
        throw std::invalid_argument(fmt::format("{}: unknown option", arg));
      }
    } catch (const std::logic_error& e) {
      if (dynamic_cast<const std::invalid_argument*>(&e) != nullptr &&
          std::string(e.what()).starts_with(arg))
        throw;
      throw std::invalid_argument(fmt::format("{}: expected integers, got '{}'", arg, value));
    }
  }
  if (o.algorithms.empty() || o.uavs.empty() || o.seeds < 1)
    throw std::invalid_argument("expected at least one algorithm, fleet size and seed");
  return o;
}

struct Cost {
  std::vector<double> seconds;
  int incomplete = 0;
};

Cost measure(const std::string& algorithm, const Options& o, const world::HullMask& hull) {
  planners::PartitionCache cache;
  planners::MissionOptions options;
  options.partitions = &cache;
  Cost cost;
  for (const char* scenario : {"perfect", "imperfect", "inhomogeneous", "combined"}) {
    for (const int s2 : {7, 9, 11}) {
      for (const int n : o.uavs) {
        for (int seed = 1; seed <= o.seeds; ++seed) {
          const auto spec = bench::paper_grid_mission(algorithm, scenario, s2, n, seed, hull);
          const double start = thread_cpu_seconds();
          const sim::MissionResult r = planners::run_mission(spec, hull, options);
          cost.seconds.push_back(thread_cpu_seconds() - start);
          cost.incomplete += r.complete ? 0 : 1;
        }
      }
    }
  }
  return cost;
}

double mean(const std::vector<double>& v) {
  double sum = 0;
  for (const double x : v) sum += x;
  return sum / static_cast<double>(v.size());
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    const world::HullMask& hull = world::default_hull();
    double lawnmower = 0;
    {
      const Cost base = measure("lawnmower", o, hull);
      lawnmower = mean(base.seconds);
    }
    fmt::print("{:<16} {:>8} {:>9} {:>9} {:>12} {:>10}\n", "planner", "missions", "mean ms",
               "median ms", "x lawnmower", "incomplete");
    for (const std::string& algorithm : o.algorithms) {
      const Cost cost = measure(algorithm, o, hull);
      const double m = mean(cost.seconds);
      fmt::print("{:<16} {:>8} {:>9.3f} {:>9.3f} {:>12.2f} {:>10}\n", algorithm,
                 cost.seconds.size(), 1e3 * m, 1e3 * median(cost.seconds), m / lawnmower,
                 cost.incomplete);
      std::fflush(stdout);
    }
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "mission_cost_bench: {}\n", e.what());
    return 2;
  }
}
