// What the layers of the physical mission cost the computer (docs/results.md, "What the layers
// cost"): every mission of the paper preset's grid (four scenarios × s2 ∈ {7, 9, 11} × n = 4 … 8 ×
// seeds, the preset's planners and options, partitions cached per planner as in an experiment)
// flown in the paper's model and as a physical mission with all the layers at work: one launch
// site at the middle of the bottom edge (115, 0) whose take-offs and landings are sequenced,
// batteries (sortie layer) and separation D (deconfliction layer). Times are CPU time of this
// thread, so the other load on the machine does not count.
//
//   build/release/bench/layer_cost_bench                       # seeds 1-3, 360 s, D = 1
//   build/release/bench/layer_cost_bench --seeds 1 --separation 3 --endurance 600
//   build/release/bench/layer_cost_bench --algorithms lawnmower,sweep-inspect
//
// Per planner: missions; median CPU ms per mission in the paper's model and in the physical
// mission, and the ratio of their sums; mean steps per mission and CPU µs per step of each; the
// layers' share of the physical missions' CPU, summed over the missions, and its largest value in
// one mission; the physical missions that did not complete, crashed a battery or flew a conflict.
//
// The layers' share: each physical mission is flown once more with the sortie layer's and the
// deconfliction layer's calls timed inside the mission loop (MissionOptions::layer_seconds). A
// timed interval also holds about one read of the clock (some 0.5 µs on a virtual machine, as
// much as the layers' own work), so the read's CPU, measured before each planner, is taken off
// for each of the two intervals of every step; the share is over the CPU of the untimed flight.
// The share with the clock reads left in is printed too (raw).

#include <fmt/format.h>

#include <algorithm>
#include <functional>
#include <map>
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

struct Options {
  std::vector<std::string> algorithms{"lawnmower", "part-tsp", "part-tsp0", "coop-frontier"};
  int seeds = 3;
  double endurance = 360;
  int separation = 1;
};

Options parse(int argc, char** argv) {
  Options o;
  // Each option takes one value: a name-to-reader table, read in pairs.
  const std::map<std::string, std::function<void(const std::string&)>> readers = {
      {"--algorithms", [&](const std::string& v) { o.algorithms = bench::split(v, ','); }},
      {"--seeds", [&](const std::string& v) { o.seeds = std::stoi(v); }},
      {"--endurance", [&](const std::string& v) { o.endurance = std::stod(v); }},
      {"--separation", [&](const std::string& v) { o.separation = std::stoi(v); }}};
  for (int i = 1; i < argc; i += 2) {
    const std::string arg = argv[i];
    const auto reader = readers.find(arg);
    if (reader == readers.end()) throw std::invalid_argument(arg + ": unknown option");
    if (i + 1 >= argc) throw std::invalid_argument(arg + ": expected a value");
    try {
      reader->second(argv[i + 1]);
    } catch (const std::logic_error&) {
      throw std::invalid_argument(arg + ": expected a number, got '" + argv[i + 1] + "'");
    }
  }
  if (o.algorithms.empty() || o.seeds < 1 || o.endurance <= 0 || o.separation < 1)
    throw std::invalid_argument(
        "expected at least one algorithm and seed, an endurance > 0 and a separation ≥ 1");
  return o;
}

/// The CPU one timed interval adds to what it measures: the median over a few batches of empty
/// intervals timed as the mission loop times the layers.
double clock_read_seconds() {
  std::vector<double> batches;
  for (int b = 0; b < 5; ++b) {
    constexpr int kIntervals = 20000;
    double inside = 0;
    for (int i = 0; i < kIntervals; ++i) {
      const double start = bench::thread_cpu_seconds();
      inside += bench::thread_cpu_seconds() - start;
    }
    batches.push_back(inside / kIntervals);
  }
  return bench::median(batches);
}

/// The missions of one planner in one model.
struct Flown {
  std::vector<double> seconds;  ///< CPU per mission
  double total_seconds = 0;
  long long steps = 0;
  double layer_seconds = 0;        ///< the layers' CPU (the reads taken off), summed
  double timed_seconds = 0;        ///< CPU of the flights with the layers timed, summed
  double raw_layer_seconds = 0;    ///< the layers' CPU with the reads left in, summed
  double largest_layer_share = 0;  ///< its largest value in one mission, over the mission's CPU
  int incomplete = 0;
  int crashed = 0;     ///< missions with a battery crash
  int conflicted = 0;  ///< missions with a separation conflict
};

planners::MissionSpec mission(const std::string& algorithm, const Options& o, bool physical,
                              const char* scenario, int s2, int n, int seed,
                              const world::HullMask& hull) {
  planners::MissionSpec spec = bench::paper_grid_mission(algorithm, scenario, s2, n, seed, hull);
  if (physical) {
    spec.params.launch_sites = {{115, 0}};
    spec.params.endurance_s = o.endurance;
    spec.params.separation = o.separation;
  }
  return spec;
}

Flown fly(const std::string& algorithm, const Options& o, bool physical, double clock_read,
          const world::HullMask& hull) {
  planners::PartitionCache cache;
  planners::MissionOptions options;
  options.partitions = &cache;
  Flown flown;
  for (const char* scenario : {"perfect", "imperfect", "inhomogeneous", "combined"}) {
    for (const int s2 : {7, 9, 11}) {
      for (int n = 4; n <= 8; ++n) {
        for (int seed = 1; seed <= o.seeds; ++seed) {
          const auto spec = mission(algorithm, o, physical, scenario, s2, n, seed, hull);
          options.layer_seconds = nullptr;
          double start = bench::thread_cpu_seconds();
          const sim::MissionResult r = planners::run_mission(spec, hull, options);
          const double seconds = bench::thread_cpu_seconds() - start;
          flown.seconds.push_back(seconds);
          flown.total_seconds += seconds;
          flown.steps += r.steps;
          flown.incomplete += r.complete ? 0 : 1;
          flown.crashed += r.battery_crashes > 0 ? 1 : 0;
          flown.conflicted += r.separation_conflicts > 0 ? 1 : 0;
          if (!physical) continue;
          double layers = 0;
          options.layer_seconds = &layers;
          start = bench::thread_cpu_seconds();
          planners::run_mission(spec, hull, options);
          flown.timed_seconds += bench::thread_cpu_seconds() - start;
          // Two timed intervals a step: the sortie layer and the deconfliction layer.
          const double own =
              std::max(0.0, layers - 2.0 * static_cast<double>(r.steps) * clock_read);
          flown.raw_layer_seconds += layers;
          flown.layer_seconds += own;
          flown.largest_layer_share = std::max(flown.largest_layer_share, own / seconds);
        }
      }
    }
  }
  return flown;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    const world::HullMask& hull = world::default_hull();
    fmt::print("physical mission: launch site (115, 0), {} s per battery, separation {}\n",
               o.endurance, o.separation);
    fmt::print("{:<14} {:>8} {:>9} {:>9} {:>7} {:>11} {:>11} {:>8} {:>8} {:>14} {:>7} {:>14}\n",
               "planner", "missions", "paper ms", "phys. ms", "x paper", "paper steps",
               "phys. steps", "paper us", "phys. us", "layers % (max)", "raw %", "inc/crash/conf");
    for (const std::string& algorithm : o.algorithms) {
      const double clock_read = clock_read_seconds();
      const Flown paper = fly(algorithm, o, false, clock_read, hull);
      const Flown physical = fly(algorithm, o, true, clock_read, hull);
      const auto missions = static_cast<double>(paper.seconds.size());
      fmt::print(
          "{:<14} {:>8} {:>9.3f} {:>9.3f} {:>7.2f} {:>11.1f} {:>11.1f} {:>8.2f} {:>8.2f} "
          "{:>6.1f} ({:>5.1f}) {:>7.1f} {:>8}/{}/{}\n",
          algorithm, paper.seconds.size(), 1e3 * bench::median(paper.seconds),
          1e3 * bench::median(physical.seconds), physical.total_seconds / paper.total_seconds,
          static_cast<double>(paper.steps) / missions,
          static_cast<double>(physical.steps) / missions,
          1e6 * paper.total_seconds / static_cast<double>(paper.steps),
          1e6 * physical.total_seconds / static_cast<double>(physical.steps),
          100 * physical.layer_seconds / physical.total_seconds, 100 * physical.largest_layer_share,
          100 * physical.raw_layer_seconds / physical.timed_seconds, physical.incomplete,
          physical.crashed, physical.conflicted);
      fmt::print("  (a clock read inside a timed interval: {:.0f} ns)\n", 1e9 * clock_read);
      std::fflush(stdout);
    }
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "layer_cost_bench: {}\n", e.what());
    return 2;
  }
}
