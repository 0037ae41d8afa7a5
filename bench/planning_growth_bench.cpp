// How each planner's planning time grows with the hull: every registered planner (or --algorithms)
// flies one mission on the default hull profile at 1×, 2×, 4× and 8× its area, for each fleet
// size and scenario, and the table gives its planner CPU seconds (MissionResult::planner_seconds,
// the median of --repeats missions) and the slope of the least-squares line through
// log(seconds) against log(area): 1 is linear in the hull, 2 quadratic. With --dtc, the same
// planners plan the DTC hull (Debian's openfoam-examples) for each of --dtc-uavs.
//
//   build/release/bench/planning_growth_bench
//   build/release/bench/planning_growth_bench --uavs 4 --scenarios perfect --algorithms
//   sweep-inspect build/release/bench/planning_growth_bench --dtc --dtc-uavs 4,8,16,32 --no-growth
//
// Partitioned planners use the `transfer` partitioner (DARP does not converge at these sizes;
// docs/results.md), Part-TSP the paper preset's r1 = 2, r2 = 0; s1 = 5, s2 = 7, seed 1, time
// limit 200 000 steps. A mission that does not complete is marked "!" after its time.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/planners/mission_spec.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/hull.hpp"
#include "hullinspect/world/mesh_hull.hpp"
#include "hullinspect/world/scenario.hpp"

#include "bench_support.hpp"

namespace {

using namespace hullinspect;

std::vector<std::string> split(const std::string& text) {
  return bench::split(text, ',');
}

struct Options {
  std::vector<std::string> algorithms;
  std::vector<int> uavs{4, 16};
  std::vector<std::string> scenarios{"perfect", "imperfect"};
  std::vector<int> dtc_uavs{4, 8, 16, 32};
  int repeats = 1;
  bool growth = true;
  bool dtc = false;
  std::string csv;
};

std::vector<int> numbers(const std::string& text, const char* option) {
  std::vector<int> out;
  for (const std::string& item : split(text)) {
    try {
      out.push_back(std::stoi(item));
    } catch (const std::exception&) {
      throw std::invalid_argument(fmt::format("{}: expected comma-separated integers", option));
    }
  }
  return out;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::invalid_argument(fmt::format("{}: expected a value", arg));
      return argv[++i];
    };
    if (arg == "--algorithms") {
      o.algorithms = split(value());
    } else if (arg == "--uavs") {
      o.uavs = numbers(value(), "--uavs");
    } else if (arg == "--scenarios") {
      o.scenarios = split(value());
    } else if (arg == "--dtc-uavs") {
      o.dtc_uavs = numbers(value(), "--dtc-uavs");
    } else if (arg == "--repeats") {
      o.repeats = std::max(1, numbers(value(), "--repeats").front());
    } else if (arg == "--dtc") {
      o.dtc = true;
    } else if (arg == "--csv") {
      o.csv = value();
    } else if (arg == "--no-growth") {
      o.growth = false;
    } else {
      throw std::invalid_argument(fmt::format("{}: unknown option", arg));
    }
  }
  if (o.algorithms.empty()) {
    for (const auto& entry : planners::planner_registry()) o.algorithms.push_back(entry.name);
  }
  return o;
}

planners::MissionSpec spec_for(const std::string& algorithm, const std::string& scenario, int n,
                               const world::HullMask& hull) {
  planners::MissionSpec spec;
  spec.algorithm = algorithm;
  spec.params.uavs = n;
  spec.params.s2 = 7;
  spec.params.time_limit = 200'000;
  spec.corrosion = world::scenario(scenario).corrosion(hull.width());
  spec.seed = 1;
  // The partitioned planners take `transfer`; the others have no such option.
  spec.planner_options = {{"partitioner", "transfer"}};
  if (algorithm.find("part-tsp") != std::string::npos) {
    spec.planner_options["r1"] = "2";
    spec.planner_options["r2"] = "0";
  }
  try {
    planners::validate(spec, hull);
  } catch (const ParameterError&) {
    spec.planner_options.erase("partitioner");
  }
  return spec;
}

struct Timing {
  double seconds = 0;
  bool complete = true;
};

Timing median_planner_seconds(const planners::MissionSpec& spec, const world::HullMask& hull,
                              int repeats) {
  std::vector<double> seconds;
  Timing t;
  for (int r = 0; r < repeats; ++r) {
    const sim::MissionResult result = planners::run_mission(spec, hull);
    seconds.push_back(result.planner_seconds);
    t.complete = t.complete && result.complete;
  }
  std::sort(seconds.begin(), seconds.end());
  t.seconds = seconds[seconds.size() / 2];
  return t;
}

/// The least-squares slope of log(y) against log(x).
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  double mx = 0;
  double my = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    mx += std::log(x[i]);
    my += std::log(std::max(y[i], 1e-6));
  }
  mx /= static_cast<double>(x.size());
  my /= static_cast<double>(x.size());
  double sxy = 0;
  double sxx = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double dx = std::log(x[i]) - mx;
    sxy += dx * (std::log(std::max(y[i], 1e-6)) - my);
    sxx += dx * dx;
  }
  return sxy / sxx;
}

std::string cell(const Timing& t) {
  return fmt::format("{:.3f}{}", t.seconds, t.complete ? " " : "!");
}

/// Writes `text` to `path` through a temporary file renamed over it, so that a reader never sees
/// half of it.
void write_whole(const std::string& path, const std::string& text) {
  const std::string temporary = path + ".tmp";
  std::FILE* f = std::fopen(temporary.c_str(), "wb");
  if (f == nullptr) throw std::runtime_error(fmt::format("{}: cannot create", temporary));
  const bool written = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !written) {
    std::remove(temporary.c_str());
    throw std::runtime_error(fmt::format("{}: cannot write", temporary));
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    throw std::runtime_error(fmt::format("{}: cannot rename to {}", temporary, path));
  }
}

void growth(const Options& o) {
  const std::vector<world::HullMask> hulls = {
      world::default_hull(), world::load_hull(HULLINSPECT_HULL_325X42),
      world::load_hull(HULLINSPECT_HULL_460X60), world::load_hull(HULLINSPECT_HULL_650X85)};
  std::vector<double> area;
  for (const auto& hull : hulls)
    area.push_back(static_cast<double>(hull.cell_count()) / hulls.front().cell_count());
  fmt::print("Planner CPU seconds on the default hull at 1x, 2x, 4x, 8x its area ({} cells)\n",
             fmt::join(std::vector<int>{hulls[0].cell_count(), hulls[1].cell_count(),
                                        hulls[2].cell_count(), hulls[3].cell_count()},
                       ", "));
  std::string csv = "planner,scenario,n,area,hull_cells,planner_seconds,complete\n";
  fmt::print("{:<16} {:<10} {:>3} {:>9} {:>9} {:>9} {:>9} {:>7}\n", "planner", "scenario", "n",
             "x1", "x2", "x4", "x8", "slope");
  for (const std::string& algorithm : o.algorithms) {
    for (const std::string& scenario : o.scenarios) {
      for (const int n : o.uavs) {
        std::vector<Timing> times;
        std::vector<double> seconds;
        for (const auto& hull : hulls) {
          times.push_back(
              median_planner_seconds(spec_for(algorithm, scenario, n, hull), hull, o.repeats));
          seconds.push_back(times.back().seconds);
          csv += fmt::format("{},{},{},{:.4f},{},{:.6f},{}\n", algorithm, scenario, n,
                             area[seconds.size() - 1], hull.cell_count(), times.back().seconds,
                             times.back().complete ? 1 : 0);
        }
        fmt::print("{:<16} {:<10} {:>3} {:>9} {:>9} {:>9} {:>9} {:>7.2f}\n", algorithm, scenario, n,
                   cell(times[0]), cell(times[1]), cell(times[2]), cell(times[3]),
                   log_log_slope(area, seconds));
        std::fflush(stdout);
      }
    }
  }
  if (!o.csv.empty()) write_whole(o.csv, csv);
}

void dtc(const Options& o) {
  const world::HullMask hull = world::import_named_mesh_hull("dtc", world::dtc_options()).hull;
  fmt::print("\nPlanner CPU seconds on the DTC hull ({} cells), scenario {}\n", hull.cell_count(),
             o.scenarios.front());
  fmt::print("{:<16}", "planner");
  for (const int n : o.dtc_uavs) fmt::print(" {:>9}", fmt::format("n={}", n));
  fmt::print("\n");
  for (const std::string& algorithm : o.algorithms) {
    fmt::print("{:<16}", algorithm);
    for (const int n : o.dtc_uavs) {
      fmt::print(" {:>9}",
                 cell(median_planner_seconds(spec_for(algorithm, o.scenarios.front(), n, hull),
                                             hull, o.repeats)));
      std::fflush(stdout);
    }
    fmt::print("\n");
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const Options o = parse(argc, argv);
    if (o.growth) growth(o);
    if (o.dtc) dtc(o);
    return 0;
  } catch (const std::exception& e) {
    fmt::print(stderr, "planning_growth_bench: {}\n", e.what());
    return 2;
  }
}
