// Segment-TSP solvers measured at mission level: runs Part-TSP missions, records every segment
// TSP they solve (g ≥ 2), then solves each recorded instance once with every solver and reports
// per-solve CPU times (median, p99, max), proofs, and per-mission totals side by side.
//
//   tsp_mission_bench [--hull FILE] [--uavs 4,8] [--scenarios perfect,combined] [--s2 7,9,11]
//                     [--seeds N] [--solvers exact,dfj-iterative:time-limit=10,...]
//                     [--sizes 8,16,32,64,128]
//
// Defaults: the default hull, the paper's grid (four scenarios, s2 ∈ {7, 9, 11}, n = 4…8), two
// seeds, solvers exact, exact with the branch-and-cut only (dp-max-segments=0), dfj-iterative
// (time-limit=10) and heuristic. The missions themselves run with the default solver. Times are
// CPU time of the solving thread (the machine is shared: wall time measures the other jobs).
// A last table breaks the first solver's solves down by size g (buckets ending at --sizes): how
// many it proved and how long proven and unproven ones took, which is where the size above which
// a solve returns a bound instead of a proof is read off (docs/results.md).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <limits>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/mission.hpp"
#include "hullinspect/planners/part_tsp_planner.hpp"
#include "hullinspect/planners/partition_cache.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/instance.hpp"
#include "hullinspect/world/scenario.hpp"

#include "bench_support.hpp"

namespace {

using namespace hullinspect;

using bench::split;
using bench::thread_cpu_seconds;

/// The mission's solver, recording every instance it is given.
class RecordingSolver final : public tsp::TspSolver {
 public:
  RecordingSolver(std::unique_ptr<tsp::TspSolver> inner, std::vector<tsp::SegmentTsp>& out)
      : inner_(std::move(inner)), out_(out) {}
  tsp::TspSolution solve(const tsp::SegmentTsp& problem) override {
    // The mission's distance service dies with the mission, before the recorded instances are
    // solved again. These missions have no no-fly zones, so its distances are Manhattan: record
    // the instance without it (it used to keep the dangling pointer and crashed).
    out_.push_back(problem);
    out_.back().distances = nullptr;
    return inner_->solve(problem);
  }

 private:
  std::unique_ptr<tsp::TspSolver> inner_;
  std::vector<tsp::SegmentTsp>& out_;
};

std::vector<int> ints(const std::string& text) {
  std::vector<int> out;
  for (const auto& s : split(text, ',')) out.push_back(std::stoi(s));
  return out;
}

struct SolverSpec {
  std::string label, name;
  OptionMap options;
};

SolverSpec solver_spec(const std::string& text) {
  SolverSpec s;
  s.label = text;
  const auto parts = split(text, ':');
  s.name = parts.at(0);
  for (std::size_t i = 1; i < parts.size(); ++i) {
    const auto eq = parts[i].find('=');
    s.options[parts[i].substr(0, eq)] = parts[i].substr(eq + 1);
  }
  return s;
}

double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(std::ceil(q * static_cast<double>(v.size())));
  return v[std::min(v.size() - 1, rank == 0 ? 0 : rank - 1)];
}

struct Mission {
  std::string label;
  std::vector<tsp::SegmentTsp> solves;
};

/// The first solver's solves by size bucket (lo, hi]: proofs, and CPU times of the proven ones and
/// of the others.
void print_by_size(const std::string& solver, const std::vector<Mission>& missions,
                   const std::vector<double>& times, const std::vector<char>& proved,
                   std::vector<int> sizes) {
  std::sort(sizes.begin(), sizes.end());
  sizes.push_back(std::numeric_limits<int>::max());
  fmt::print(
      "\n{} by size g | solves | proven | proven: median ms | p99 ms | max ms | not proven: max "
      "ms |\n|---|---|---|---|---|---|---|\n",
      solver);
  int lo = 1;
  for (const int hi : sizes) {
    std::vector<double> proven_times;
    double unproven_max = -1;
    int solves = 0;
    std::size_t i = 0;
    for (const auto& m : missions) {
      for (const auto& p : m.solves) {
        const int g = static_cast<int>(p.segments.size());
        if (g > lo && g <= hi) {
          ++solves;
          if (proved[i])
            proven_times.push_back(times[i]);
          else
            unproven_max = std::max(unproven_max, times[i]);
        }
        ++i;
      }
    }
    if (solves > 0) {
      const std::string range = hi == std::numeric_limits<int>::max()
                                    ? fmt::format("{} <", lo)
                                    : fmt::format("{}–{}", lo + 1, hi);
      fmt::print("| {} | {} | {} | {:.3f} | {:.3f} | {:.1f} | {} |\n", range, solves,
                 proven_times.size(), 1e3 * quantile(proven_times, 0.5),
                 1e3 * quantile(proven_times, 0.99), 1e3 * quantile(proven_times, 1.0),
                 unproven_max < 0 ? std::string("—") : fmt::format("{:.1f}", 1e3 * unproven_max));
    }
    lo = hi;
  }
}

int run(int argc, char** argv) {
  std::string hull_path = "default";
  std::vector<int> uavs = {4, 5, 6, 7, 8};
  std::vector<int> s2s = {7, 9, 11};
  std::vector<std::string> scenarios = {"perfect", "imperfect", "inhomogeneous", "combined"};
  int seeds = 2;
  std::vector<int> sizes = {8, 16, 24, 32, 48, 64, 96, 128};
  std::vector<std::string> solvers = {"exact", "exact:dp-max-segments=0",
                                      "dfj-iterative:time-limit=10", "heuristic"};
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    const std::string value = argv[i + 1];
    if (key == "--hull")
      hull_path = value;
    else if (key == "--uavs")
      uavs = ints(value);
    else if (key == "--s2")
      s2s = ints(value);
    else if (key == "--scenarios")
      scenarios = split(value, ',');
    else if (key == "--seeds")
      seeds = std::stoi(value);
    else if (key == "--solvers")
      solvers = split(value, ',');
    else if (key == "--sizes")
      sizes = ints(value);
    else
      throw std::invalid_argument(fmt::format("unknown option '{}'", key));
  }
  const world::HullMask hull =
      hull_path == "default" ? world::default_hull() : world::load_hull(hull_path);
  planners::PartitionCache partitions;
  std::vector<Mission> missions;
  for (const auto& scenario_name : scenarios) {
    const auto corrosion = world::scenario(scenario_name).corrosion(hull.width());
    for (int s2 : s2s) {
      for (int n : uavs) {
        for (int seed = 1; seed <= seeds; ++seed) {
          world::MissionParams params;
          params.uavs = n;
          params.s2 = s2;
          const auto instance =
              world::generate_instance(hull, corrosion, static_cast<std::uint64_t>(seed));
          Mission m;
          m.label = fmt::format("{} s2={} n={} seed={}", scenario_name, s2, n, seed);
          planners::PartTspOptions options;
          options.r1 = 2;
          options.r2 = 0;
          planners::PartTspPlanner planner(
              options, std::make_unique<RecordingSolver>(tsp::make_tsp_solver("exact"), m.solves));
          planners::MissionOptions mo;
          mo.partitions = &partitions;
          planners::run_mission(hull, instance, params, planner, mo);
          std::erase_if(m.solves, [](const tsp::SegmentTsp& p) { return p.segments.size() < 2; });
          missions.push_back(std::move(m));
        }
      }
    }
  }
  std::size_t total = 0;
  std::size_t largest = 0;
  for (const auto& m : missions) {
    total += m.solves.size();
    for (const auto& p : m.solves) largest = std::max(largest, p.segments.size());
  }
  fmt::print("hull {} ({}x{}), {} missions, {} segment TSPs (g >= 2, largest g = {})\n\n",
             hull_path, hull.width(), hull.height(), missions.size(), total, largest);
  fmt::print(
      "| solver | solves | proven | median ms | p99 ms | max ms (g) | mission total: median ms | "
      "max ms |\n|---|---|---|---|---|---|---|---|\n");
  std::vector<std::vector<double>> per_solve(solvers.size());
  std::vector<char> first_proved;  // the first solver's proof per instance
  // Every proven optimum of an instance must be the same length whichever solver proved it.
  std::vector<long long> optimum(total, -1);
  for (std::size_t k = 0; k < solvers.size(); ++k) {
    const SolverSpec spec = solver_spec(solvers[k]);
    auto solver = tsp::make_tsp_solver(spec.name, spec.options);
    std::vector<double> times;
    std::vector<double> mission_totals;
    long long proven = 0;
    double worst = 0;
    std::size_t worst_g = 0;
    std::size_t instance = 0;
    for (const auto& m : missions) {
      double sum = 0;
      for (const auto& p : m.solves) {
        const double t0 = thread_cpu_seconds();
        const tsp::TspSolution s = solver->solve(p);
        const double t = thread_cpu_seconds() - t0;
        long long& known = optimum[instance++];
        if (s.optimal && known >= 0 && s.length != known) {
          throw std::runtime_error(fmt::format("{} proved length {} where another solver proved {}",
                                               spec.label, s.length, known));
        }
        if (s.optimal) known = s.length;
        times.push_back(t);
        if (k == 0) first_proved.push_back(s.optimal ? 1 : 0);
        sum += t;
        proven += s.optimal ? 1 : 0;
        if (t > worst) {
          worst = t;
          worst_g = p.segments.size();
        }
      }
      mission_totals.push_back(sum);
    }
    fmt::print("| {} | {} | {} | {:.3f} | {:.3f} | {:.1f} ({}) | {:.2f} | {:.1f} |\n", spec.label,
               times.size(), proven, 1e3 * quantile(times, 0.5), 1e3 * quantile(times, 0.99),
               1e3 * worst, worst_g, 1e3 * quantile(mission_totals, 0.5),
               1e3 * quantile(mission_totals, 1.0));
    per_solve[k] = std::move(times);
  }
  // Per-instance ratios of the first solver against every other (for the bake-off rule: wins at
  // mission level, never loses by more than 2× on any instance). Instances under 0.05 ms for both
  // are left out (timer resolution).
  fmt::print(
      "\n| {} against | median ratio (other / first) | worst instance (first / other) |\n"
      "|---|---|---|\n",
      solvers.front());
  for (std::size_t k = 1; k < solvers.size(); ++k) {
    std::vector<double> ratios;
    double worst = 0;
    for (std::size_t i = 0; i < per_solve[0].size(); ++i) {
      const double a = per_solve[0][i];
      const double b = per_solve[k][i];
      if (a < 5e-5 && b < 5e-5) continue;
      ratios.push_back(b / std::max(a, 1e-9));
      worst = std::max(worst, a / std::max(b, 1e-9));
    }
    fmt::print("| {} | {:.1f}x | {:.2f}x |\n", solvers[k], quantile(ratios, 0.5), worst);
  }
  print_by_size(solvers.front(), missions, per_solve.front(), first_proved, sizes);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    fmt::print(stderr, "tsp_mission_bench: {}\n", e.what());
    return 2;
  }
}
