#include "hullinspect/experiment/paired.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <functional>
#include <map>
#include <optional>
#include <set>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/planners/planner.hpp"
#include "hullinspect/world/random.hpp"

namespace hullinspect::experiment {

namespace {

// Stream id of the bootstrap ("boot"), apart from every instance stream.
constexpr std::uint64_t kBootstrapStream = 0x626f6f74;

struct Times {
  std::optional<double> t_c, t_m;
  const std::optional<double>& get(const std::string& metric) const {
    return metric == "T_c" ? t_c : t_m;
  }
};

// Per cell: algorithm → seed → times.
using CellRuns = std::map<std::string, std::map<std::string, Times>>;

std::optional<double> parse_time(const std::string& s, const std::string& source, int line,
                                 const std::string& column) {
  if (s.empty()) return std::nullopt;
  return csv_seconds(s, source, line, column);
}

// Algorithms whose planner sees the ground truth (an oracle: its registry entry says
// sees_truth) are references: compared with the others, never ranked with them and never part of
// a claim. A label's planner is read from runs.csv's planner column.
bool sees_truth(const std::string& planner) {
  const auto& registry = planners::planners();
  return registry.contains(planner) && registry.get(planner).sees_truth;
}

PairedDiff compare(const CellKey& cell, const std::string& metric, const std::string& a,
                   const std::string& b, const std::map<std::string, Times>& ra,
                   const std::map<std::string, Times>& rb, const PairedOptions& options) {
  PairedDiff d;
  d.cell = cell;
  d.metric = metric;
  d.a = a;
  d.b = b;
  std::vector<double> diffs;
  double wins = 0;
  for (const auto& [seed, ta] : ra) {
    auto it = rb.find(seed);
    if (it == rb.end() || !ta.get(metric) || !it->second.get(metric)) continue;
    const double x = *ta.get(metric) - *it->second.get(metric);
    diffs.push_back(x);
    wins += x < 0 ? 1.0 : x == 0 ? 0.5 : 0.0;
  }
  d.pairs = static_cast<int>(diffs.size());
  if (diffs.empty()) return d;
  const auto boot = bootstrap_mean(diffs, options.resamples, options.seed);
  d.mean = boot.mean;
  d.ci_low = boot.low;
  d.ci_high = boot.high;
  d.win_rate = wins / static_cast<double>(diffs.size());
  return d;
}

CellRanking rank(const CellKey& cell, const std::string& metric, const CellRuns& runs,
                 const std::set<std::string>& references,
                 const std::vector<std::string>& algorithms) {
  CellRanking r{cell, metric, 0, {}};
  std::vector<std::string> ranked;
  for (const auto& a : algorithms) {
    if (!references.contains(a) && runs.contains(a)) ranked.push_back(a);
  }
  if (ranked.empty()) return r;
  std::vector<double> rank_sum(ranked.size(), 0), value_sum(ranked.size(), 0);
  for (const auto& [seed, t0] : runs.at(ranked[0])) {
    std::vector<double> v;
    for (const auto& a : ranked) {
      auto it = runs.at(a).find(seed);
      if (it == runs.at(a).end() || !it->second.get(metric)) break;
      v.push_back(*it->second.get(metric));
    }
    if (v.size() != ranked.size()) continue;
    ++r.seeds;
    for (std::size_t i = 0; i < v.size(); ++i) {
      double below = 0, equal = 0;
      for (double w : v) {
        below += w < v[i];
        equal += w == v[i];
      }
      rank_sum[i] += below + (equal + 1) / 2;  // ties share the mean of their ranks
      value_sum[i] += v[i];
    }
  }
  if (r.seeds == 0) return r;
  for (std::size_t i = 0; i < ranked.size(); ++i) {
    r.order.push_back({ranked[i], rank_sum[i] / r.seeds, value_sum[i] / r.seeds});
  }
  std::stable_sort(r.order.begin(), r.order.end(), [](const RankEntry& x, const RankEntry& y) {
    return x.mean_rank != y.mean_rank ? x.mean_rank < y.mean_rank : x.mean < y.mean;
  });
  return r;
}

std::string seconds(double v) {
  return fmt::format("{:.1f}", v);
}

std::string cell_name(const CellKey& c) {
  return fmt::format("{}, s2 = {}, n = {}", c.scenario, c.s2, c.uavs);
}

std::string diff_text(const PairedDiff& d) {
  return fmt::format("{} [{}, {}] s, {:.0f} % wins", seconds(d.mean), seconds(d.ci_low),
                     seconds(d.ci_high), 100 * d.win_rate);
}

}  // namespace

BootstrapMean bootstrap_mean(const std::vector<double>& values, int resamples, std::uint64_t seed) {
  BootstrapMean out;
  if (values.empty()) return out;
  double sum = 0;
  for (double v : values) sum += v;
  const auto n = values.size();
  out.mean = sum / static_cast<double>(n);
  if (n == 1 || resamples < 1) {
    out.low = out.high = out.mean;
    return out;
  }
  world::RandomStream random(seed, kBootstrapStream);
  std::vector<double> means(static_cast<std::size_t>(resamples));
  for (auto& m : means) {
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += values[random.below(n)];
    m = s / static_cast<double>(n);
  }
  std::sort(means.begin(), means.end());
  const auto at = [&](double q) {
    const auto i = static_cast<std::size_t>(std::floor(q * static_cast<double>(resamples - 1)));
    return means[std::min(i, means.size() - 1)];
  };
  out.low = at(0.025);
  out.high = at(0.975);
  return out;
}

const PairedDiff* PairedAnalysis::find(const CellKey& cell, const std::string& metric,
                                       const std::string& a, const std::string& b) const {
  for (const auto& d : diffs) {
    if (d.cell == cell && d.metric == metric && d.a == a && d.b == b && d.pairs > 0) return &d;
  }
  return nullptr;
}

std::vector<CellKey> PairedAnalysis::cells() const {
  std::vector<CellKey> out;
  for (const auto& r : rankings) {
    if (std::find(out.begin(), out.end(), r.cell) == out.end()) out.push_back(r.cell);
  }
  return out;
}

PairedAnalysis analyse_pairs(const CsvTable& runs, const std::string& source,
                             const PairedOptions& options) {
  const int c_scenario = runs.column("scenario", source);
  const int c_algorithm = runs.column("algorithm", source);
  const int c_planner = runs.column("planner", source);
  const int c_s2 = runs.column("s2", source);
  const int c_uavs = runs.column("uavs", source);
  const int c_seed = runs.column("seed", source);
  const int c_tc = runs.column("T_c", source);
  const int c_tm = runs.column("T_m", source);

  std::vector<CellKey> cell_order;
  std::map<CellKey, CellRuns> data;
  std::vector<std::string> seen;
  std::set<std::string> references;
  int line = 1;
  for (const auto& r : runs.rows) {
    ++line;
    auto at = [&](int c) -> const std::string& { return r[static_cast<std::size_t>(c)]; };
    const CellKey key{at(c_scenario), csv_int(at(c_s2), source, line, "s2"),
                      csv_int(at(c_uavs), source, line, "uavs")};
    if (!data.contains(key)) cell_order.push_back(key);
    const auto& algorithm = at(c_algorithm);
    if (std::find(seen.begin(), seen.end(), algorithm) == seen.end()) seen.push_back(algorithm);
    if (sees_truth(at(c_planner))) references.insert(algorithm);
    data[key][algorithm][at(c_seed)] =
        Times{parse_time(at(c_tc), source, line, "T_c"), parse_time(at(c_tm), source, line, "T_m")};
  }

  PairedAnalysis out;
  out.algorithms = options.algorithms.empty() ? seen : options.algorithms;
  out.references = references;
  for (const auto& a : out.algorithms) {
    if (std::find(seen.begin(), seen.end(), a) == seen.end()) {
      std::string known;
      for (const auto& s : seen) known += (known.empty() ? "" : ", ") + s;
      throw InputError(source, 0,
                       fmt::format("no runs of algorithm '{}' (the runs hold: {})", a, known));
    }
  }
  for (const auto& cell : cell_order) {
    const auto& cr = data.at(cell);
    for (const auto& metric : options.metrics) {
      out.rankings.push_back(rank(cell, metric, cr, out.references, out.algorithms));
      for (std::size_t i = 0; i < out.algorithms.size(); ++i) {
        for (std::size_t j = i + 1; j < out.algorithms.size(); ++j) {
          const auto &a = out.algorithms[i], &b = out.algorithms[j];
          if (!cr.contains(a) || !cr.contains(b)) continue;
          out.diffs.push_back(compare(cell, metric, a, b, cr.at(a), cr.at(b), options));
        }
      }
    }
  }
  return out;
}

namespace {

// a − b from the analysis whichever order it was computed in.
std::optional<PairedDiff> diff_of(const PairedAnalysis& an, const CellKey& cell,
                                  const std::string& metric, const std::string& a,
                                  const std::string& b) {
  if (const auto* d = an.find(cell, metric, a, b)) return *d;
  if (const auto* d = an.find(cell, metric, b, a)) {
    PairedDiff r = *d;
    std::swap(r.a, r.b);
    r.mean = -d->mean;
    r.ci_low = -d->ci_high;
    r.ci_high = -d->ci_low;
    r.win_rate = 1 - d->win_rate;
    return r;
  }
  return std::nullopt;
}

// A claim "a is faster (sign −1) / slower (+1) than each b by the metric" over the cells that
// `in_scope` selects; `most` = holding in more than half of the comparisons suffices.
ClaimCheck directional_claim(const PairedAnalysis& an, std::string id, std::string claim,
                             const std::function<bool(const CellKey&)>& in_scope,
                             const std::string& metric, const std::string& a,
                             const std::vector<std::string>& others, int sign, bool most) {
  ClaimCheck c{std::move(id), std::move(claim), {}, {}};
  int total = 0, held = 0;
  std::optional<PairedDiff> weakest;
  for (const auto& cell : an.cells()) {
    if (!in_scope(cell)) continue;
    for (const auto& b : others) {
      const auto d = diff_of(an, cell, metric, a, b);
      if (!d) continue;
      ++total;
      const bool ok = d->verdict() == sign;
      held += ok;
      // The weakest comparison: the interval end nearest to (or beyond) zero, in the claim's
      // direction.
      const double margin = sign < 0 ? -d->ci_high : d->ci_low;
      const double weakest_margin = !weakest ? 0 : (sign < 0 ? -weakest->ci_high : weakest->ci_low);
      if (!weakest || margin < weakest_margin) weakest = d;
    }
  }
  if (total == 0) {
    c.verdict = "not testable";
    c.evidence = "the experiment has no cell with these algorithms and scenario";
    return c;
  }
  const bool ok = most ? 2 * held > total : held == total;
  c.verdict = ok          ? "held"
              : held == 0 ? "not held"
                          : fmt::format("partly held ({} of {})", held, total);
  c.evidence = fmt::format(
      "{} of {} paired comparisons have the 95 % interval on the claimed side; weakest: {} − {} "
      "({}): {}",
      held, total, weakest->a, weakest->b, cell_name(weakest->cell), diff_text(*weakest));
  return c;
}

}  // namespace

std::vector<ClaimCheck> check_paper_claims(const PairedAnalysis& an) {
  const std::string tsp = "part-tsp", tsp0 = "part-tsp0", coop = "coop-frontier",
                    lawn = "lawnmower";
  auto scenario = [](std::string s) {
    return [s = std::move(s)](const CellKey& c) { return c.scenario == s; };
  };
  auto not_combined = [](const CellKey& c) { return c.scenario != "combined"; };
  auto any = [](const CellKey&) { return true; };
  std::vector<ClaimCheck> out;
  out.push_back(directional_claim(
      an, "C1",
      "Perfect information: Part-TSP achieves considerably smaller T_c than the other algorithms "
      "(V-B.1, Fig. 6 a1)",
      scenario("perfect"), "T_c", tsp, {lawn, tsp0, coop}, -1, false));
  out.push_back(directional_claim(
      an, "C2",
      "Perfect information: Part-TSP's better c(t) comes at the cost of a slightly worse T_m than "
      "Part-TSP0 (V-B.1, Fig. 6 a2)",
      scenario("perfect"), "T_m", tsp, {tsp0}, +1, false));
  out.push_back(directional_claim(
      an, "C3",
      "Perfect information: Coop-Frontier has a greater T_c than Part-TSP0 (V-B.1, Fig. 6 a1)",
      scenario("perfect"), "T_c", coop, {tsp0}, +1, false));
  out.push_back(directional_claim(
      an, "C4a",
      "Part-TSP inspects corrosion faster (T_c) than the lawnmower (conclusion 1), every scenario",
      any, "T_c", tsp, {lawn}, -1, false));
  out.push_back(directional_claim(
      an, "C4b",
      "Coop-Frontier inspects corrosion faster (T_c) than the lawnmower (conclusion 1), every "
      "scenario",
      any, "T_c", coop, {lawn}, -1, false));
  out.push_back(directional_claim(
      an, "C5",
      "Part-TSP performs better (T_c) than Coop-Frontier in most cases (conclusion 2; scenarios "
      "other than combined)",
      not_combined, "T_c", tsp, {coop}, -1, true));
  out.push_back(directional_claim(
      an, "C6",
      "All imperfections together (combined scenario): Coop-Frontier outperforms all other "
      "algorithms in T_c (V-B.2, Fig. 8 c2)",
      scenario("combined"), "T_c", coop, {lawn, tsp, tsp0}, -1, false));

  // C7: the spread of mean T_c between the algorithms shrinks as the fleet grows (perfect
  // scenario).
  ClaimCheck c7{"C7",
                "Perfect information: the difference between the algorithms (T_c) is more "
                "prominent for smaller fleets (V-B.1)",
                {},
                {}};
  std::map<int, std::map<int, double>> spread;  // s2 → n → max − min of the ranking means
  for (const auto& r : an.rankings) {
    if (r.cell.scenario != "perfect" || r.metric != "T_c" || r.order.size() < 2) continue;
    double lo = r.order[0].mean, hi = lo;
    for (const auto& e : r.order) lo = std::min(lo, e.mean), hi = std::max(hi, e.mean);
    spread[r.cell.s2][r.cell.uavs] = hi - lo;
  }
  int tested = 0, held = 0;
  std::string evidence;
  for (const auto& [s2, by_n] : spread) {
    if (by_n.size() < 2) continue;
    const auto& [n_small, small] = *by_n.begin();
    const auto& [n_large, large] = *by_n.rbegin();
    ++tested;
    held += small > large;
    evidence +=
        fmt::format("{}s2 = {}: {} s at n = {}, {} s at n = {}", evidence.empty() ? "" : "; ", s2,
                    seconds(small), n_small, seconds(large), n_large);
  }
  if (tested == 0) {
    c7.verdict = "not testable";
    c7.evidence = "needs the perfect scenario at two fleet sizes";
  } else {
    c7.verdict = held == tested ? "held"
                 : held == 0    ? "not held"
                                : fmt::format("partly held ({} of {})", held, tested);
    c7.evidence = "largest − smallest mean T_c over the algorithms: " + evidence;
  }
  out.push_back(c7);
  return out;
}

std::string paired_markdown(const PairedAnalysis& an, const std::vector<ClaimCheck>& claims) {
  std::string md;
  md += "## The paper's claims\n\n";
  md +=
      "Checked with the paired differences below: a comparison supports a claim when its 95 % "
      "bootstrap interval lies entirely on the claimed side of zero.\n\n";
  md += "| claim | verdict | evidence |\n|---|---|---|\n";
  for (const auto& c : claims) {
    md += fmt::format("| {}: {} | **{}** | {} |\n", c.id, c.claim, c.verdict, c.evidence);
  }
  md += "\n## Paired comparisons\n\n";
  md +=
      "Per scenario cell, over the seeds both algorithms share: the mean of a − b in seconds "
      "(negative: a is faster), its 95 % percentile-bootstrap interval (2000 resamples, fixed "
      "seed) and the share of seeds where a was faster (ties count one half). The ranking orders "
      "the algorithms by their mean rank over the seeds where all of them reached the time.";
  bool references = false;
  for (const auto& a : an.algorithms) references = references || an.references.contains(a);
  if (references) {
    md += " Algorithms that see the ground truth (oracles, bounds) are compared but not ranked.";
  }
  md += "\n\n";
  for (const auto& cell : an.cells()) {
    md += fmt::format("### {}\n\n", cell_name(cell));
    for (const auto& r : an.rankings) {
      if (!(r.cell == cell) || r.order.empty()) continue;
      md += fmt::format("- {} ranking ({}): ", r.metric, plural(r.seeds, "seed"));
      for (std::size_t i = 0; i < r.order.size(); ++i) {
        md += fmt::format("{}{} (mean rank {:.2f}, {} s)", i == 0 ? "" : " < ",
                          r.order[i].algorithm, r.order[i].mean_rank, seconds(r.order[i].mean));
      }
      md += "\n";
    }
    md +=
        "\n| a − b | pairs | T_c: mean [95 % CI] | a faster | T_m: mean [95 % CI] | a faster |\n"
        "|---|---:|---:|---:|---:|---:|\n";
    for (std::size_t i = 0; i < an.algorithms.size(); ++i) {
      for (std::size_t j = i + 1; j < an.algorithms.size(); ++j) {
        const auto* tc = an.find(cell, "T_c", an.algorithms[i], an.algorithms[j]);
        const auto* tm = an.find(cell, "T_m", an.algorithms[i], an.algorithms[j]);
        if (tc == nullptr && tm == nullptr) continue;
        auto cols = [](const PairedDiff* d) {
          if (d == nullptr) return std::string("— | —");
          return fmt::format("{} [{}, {}] | {:.0f} %", seconds(d->mean), seconds(d->ci_low),
                             seconds(d->ci_high), 100 * d->win_rate);
        };
        md += fmt::format("| {} − {} | {} | {} | {} |\n", an.algorithms[i], an.algorithms[j],
                          tc != nullptr ? tc->pairs : tm->pairs, cols(tc), cols(tm));
      }
    }
    md += "\n";
  }
  return md;
}

std::string paired_csv(const PairedAnalysis& an) {
  std::string out = csv_line({"scenario", "s2", "uavs", "metric", "a", "b", "pairs", "mean_diff",
                              "ci_low", "ci_high", "win_rate"}) +
                    "\n";
  for (const auto& d : an.diffs) {
    out += csv_line({d.cell.scenario, std::to_string(d.cell.s2), std::to_string(d.cell.uavs),
                     d.metric, d.a, d.b, std::to_string(d.pairs), fmt::format("{:.3f}", d.mean),
                     fmt::format("{:.3f}", d.ci_low), fmt::format("{:.3f}", d.ci_high),
                     fmt::format("{:.4f}", d.win_rate)}) +
           "\n";
  }
  return out;
}

}  // namespace hullinspect::experiment
