// Segment-TSP solvers on the mission-like instances of bench/tsp_instances/ (written by
// tools/make_tsp_instances.py; g = 5, 10, 20, 40, 80, 20 instances each).
//
//   tsp_bench                 Google Benchmark: BM_Solve/<solver>/<g>, each iteration solves the
//                             next instance of size g (time = mean over the instances)
//   tsp_bench --table [--time-limit S] [--sizes 5,10,...] [--solvers a,b:key=value,...]
//                             the side-by-side table of docs/tsp.md: per solver and g, the median
//                             and 95th-percentile (nearest rank) time over the instances, each
//                             instance's time being the median of repeated solves (repeated until
//                             50 ms or 50 solves); lengths checked against "exact"'s proven optima;
//                             heuristic gaps. Times are CPU time of the solving thread (the machine
//                             the table was made on is shared; wall time would measure the others).
//                             exact and dfj-iterative get the time limit S (wall clock, default
//                             60).

#include <benchmark/benchmark.h>
#include "source_dir.hpp"
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "hullinspect/io/tsp_json.hpp"
#include "hullinspect/tsp/segment_tsp.hpp"

namespace {

using namespace hullinspect;

std::vector<tsp::SegmentTsp> load_instances(int g) {
  const std::filesystem::path dir =
      std::filesystem::path(HULLINSPECT_SOURCE_DIR) / "bench/tsp_instances";
  std::vector<std::filesystem::path> files;
  const std::string prefix = fmt::format("g{:03d}_", g);
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    if (entry.path().filename().string().starts_with(prefix)) files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::vector<tsp::SegmentTsp> out;
  for (const auto& f : files) out.push_back(io::read_tsp_instance(f));
  return out;
}

const std::vector<tsp::SegmentTsp>& instances(int g) {
  static std::map<int, std::vector<tsp::SegmentTsp>> cache;
  auto it = cache.find(g);
  if (it == cache.end()) it = cache.emplace(g, load_instances(g)).first;
  return it->second;
}

void BM_Solve(benchmark::State& state, const std::string& solver_name) {
  const auto& set = instances(static_cast<int>(state.range(0)));
  auto solver = tsp::make_tsp_solver(solver_name);
  std::size_t next = 0;
  for (auto _ : state) {
    auto solution = solver->solve(set[next]);
    benchmark::DoNotOptimize(solution.length);
    next = (next + 1) % set.size();
  }
}

void register_benchmarks() {
  for (const char* name : {"exact", "heuristic"}) {
    benchmark::RegisterBenchmark(fmt::format("BM_Solve/{}", name).c_str(), BM_Solve, name)
        ->ArgName("g")
        ->Arg(5)
        ->Arg(10)
        ->Arg(20)
        ->Arg(40)
        ->Arg(80)
        ->Unit(benchmark::kMicrosecond);
  }
  benchmark::RegisterBenchmark("BM_Solve/dfj-iterative", BM_Solve, "dfj-iterative")
      ->ArgName("g")
      ->Arg(5)
      ->Arg(10)
      ->Arg(20)
      ->Unit(benchmark::kMillisecond);
}

// ---- side-by-side table ---------------------------------------------------------------------

struct Timed {
  tsp::TspSolution solution;
  double seconds = 0;  // median over the repeats
};

double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

Timed timed_solve(tsp::TspSolver& solver, const tsp::SegmentTsp& problem) {
  std::vector<double> times;
  Timed out;
  double total = 0;
  while (times.empty() || (total < 0.05 && times.size() < 50)) {
    const double t0 = thread_seconds();
    out.solution = solver.solve(problem);
    const double s = thread_seconds() - t0;
    times.push_back(s);
    total += s;
  }
  std::sort(times.begin(), times.end());
  out.seconds = times[times.size() / 2];
  return out;
}

double percentile(std::vector<double> values, double p) {  // nearest rank
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(std::ceil(p * static_cast<double>(values.size())));
  return values[std::max<std::size_t>(rank, 1) - 1];
}

std::vector<std::string> split(const std::string& text) {
  std::vector<std::string> out;
  std::size_t from = 0;
  while (from <= text.size()) {
    const auto comma = text.find(',', from);
    out.push_back(text.substr(from, comma == std::string::npos ? std::string::npos : comma - from));
    if (comma == std::string::npos) break;
    from = comma + 1;
  }
  return out;
}

int run_table(int argc, char** argv) {
  std::vector<int> sizes = {5, 10, 20, 40, 80};
  std::vector<std::string> solvers = {"exact", "heuristic", "dfj-iterative"};
  double time_limit = 60;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--time-limit" && i + 1 < argc) time_limit = std::stod(argv[++i]);
    if (arg == "--sizes" && i + 1 < argc) {
      sizes.clear();
      for (const auto& s : split(argv[++i])) sizes.push_back(std::stoi(s));
    }
    if (arg == "--solvers" && i + 1 < argc) solvers = split(argv[++i]);
  }
  std::erase(solvers, std::string("exact"));
  solvers.insert(solvers.begin(), "exact");  // first: its proven optima are the reference
  std::cout
      << "| g | solver | median ms | p95 ms | proven optimal | = optimum | mean gap % | worst "
         "gap % |\n|---|---|---|---|---|---|---|---|\n";
  for (int g : sizes) {
    const auto& set = instances(g);
    std::vector<tsp::TspSolution> reference;
    std::map<std::string, double> medians;
    for (const auto& spec : solvers) {
      // "name" or "name:key=value" (one extra solver option, e.g. heuristic:kicks=20).
      const std::string name = spec.substr(0, spec.find(':'));
      OptionMap options;
      if (name != "heuristic") options["time_limit"] = fmt::format("{}", time_limit);
      if (const auto colon = spec.find(':'); colon != std::string::npos) {
        const std::string kv = spec.substr(colon + 1);
        options[kv.substr(0, kv.find('='))] = kv.substr(kv.find('=') + 1);
      }
      auto solver = tsp::make_tsp_solver(name, options);
      std::vector<double> times, gaps;
      int proven = 0, equal = 0, comparable = 0;
      for (std::size_t i = 0; i < set.size(); ++i) {
        const Timed t = timed_solve(*solver, set[i]);
        if (name == "exact") reference.push_back(t.solution);
        times.push_back(t.seconds * 1e3);
        if (t.solution.optimal) ++proven;
        if (reference[i].optimal) {
          ++comparable;
          if (t.solution.length == reference[i].length) ++equal;
          if (t.solution.optimal && t.solution.length != reference[i].length) {
            std::cerr << fmt::format("MISMATCH g = {} instance {}: {} proves {}, exact {}\n", g, i,
                                     name, t.solution.length, reference[i].length);
          }
          gaps.push_back(100.0 * static_cast<double>(t.solution.length - reference[i].length) /
                         static_cast<double>(std::max(1LL, reference[i].length)));
        }
      }
      medians[spec] = percentile(times, 0.5);
      double mean_gap = 0, worst_gap = 0;
      for (double v : gaps) {
        mean_gap += v / static_cast<double>(gaps.size());
        worst_gap = std::max(worst_gap, v);
      }
      std::cout << fmt::format("| {} | {} | {:.3f} | {:.3f} | {}/{} | {}/{} | {:.2f} | {:.2f} |\n",
                               g, name, percentile(times, 0.5), percentile(times, 0.95), proven,
                               set.size(), equal, comparable, mean_gap, worst_gap);
      std::cout.flush();
    }
    if (medians.contains("dfj-iterative")) {
      std::cout << fmt::format("|   | dfj-iterative / exact (medians) | {:.0f}× | | | | | |\n",
                               medians["dfj-iterative"] / medians["exact"]);
    }
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--table") == 0) return run_table(argc, argv);
  }
  register_benchmarks();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
