#include "hullinspect/experiment/summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <tuple>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/experiment/paired.hpp"

namespace hullinspect::experiment {

namespace {

TimeStats stats(const std::vector<double>& v) {
  TimeStats s;
  s.count = static_cast<int>(v.size());
  if (v.empty()) return s;
  double sum = 0;
  for (double x : v) sum += x;
  s.mean = sum / static_cast<double>(v.size());
  if (v.size() > 1) {
    double sq = 0;
    for (double x : v) sq += (x - s.mean) * (x - s.mean);
    s.std = std::sqrt(sq / static_cast<double>(v.size() - 1));
  }
  const PairedOptions report;  // the report's bootstrap: its resamples and seed
  const BootstrapMean interval = bootstrap_mean(v, report.resamples, report.seed);
  s.ci_low = interval.low;
  s.ci_high = interval.high;
  return s;
}

std::string mean_std(const TimeStats& t) {
  if (t.count == 0) return "—";
  return fmt::format("{:.1f} ± {:.1f}", t.mean, t.std);
}

/// Display width in characters (UTF-8 aware: counts code points).
std::size_t width(const std::string& s) {
  std::size_t n = 0;
  for (unsigned char c : s) n += (c & 0xC0) != 0x80;
  return n;
}

std::string table(const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> w(rows[0].size(), 3);
  for (const auto& r : rows) {
    for (std::size_t i = 0; i < r.size(); ++i) w[i] = std::max(w[i], width(r[i]));
  }
  std::string out;
  for (std::size_t r = 0; r < rows.size(); ++r) {
    out += '|';
    for (std::size_t i = 0; i < rows[r].size(); ++i) {
      const std::size_t fill = w[i] - width(rows[r][i]);
      out += ' ';
      if (r > 0) out.append(fill, ' ');  // numbers right-aligned
      out += rows[r][i];
      if (r == 0) out.append(fill, ' ');
      out += " |";
    }
    out += '\n';
    if (r == 0) {
      out += '|';
      for (std::size_t i = 0; i < rows[r].size(); ++i) {
        out += ' ';
        out.append(w[i] - 1, '-');
        out += ": |";
      }
      out += '\n';
    }
  }
  return out;
}

}  // namespace

std::vector<SummaryRow> summarize_runs(const CsvTable& runs, const std::string& source) {
  const int c_scenario = runs.column("scenario", source);
  const int c_sweep = runs.column("sweep", source);
  const int c_value = runs.column("sweep_value", source);
  const int c_algorithm = runs.column("algorithm", source);
  const int c_s2 = runs.column("s2", source);
  const int c_uavs = runs.column("uavs", source);
  const int c_complete = runs.column("complete", source);
  const int c_tc = runs.column("T_c", source);
  const int c_tm = runs.column("T_m", source);
  const int c_btc = runs.find_column("bound_T_c");
  const int c_btm = runs.find_column("bound_T_m");

  std::vector<SummaryRow> rows;
  std::vector<std::vector<double>> tc, tm, btc, btm;
  std::map<std::tuple<std::string, int, int, std::string>, std::size_t> index;
  int line = 1;
  for (const auto& r : runs.rows) {
    ++line;
    auto at = [&](int c) -> const std::string& { return r[static_cast<std::size_t>(c)]; };
    const int s2 = csv_int(at(c_s2), source, line, "s2");
    const int uavs = csv_int(at(c_uavs), source, line, "uavs");
    const auto key = std::make_tuple(at(c_scenario), s2, uavs, at(c_algorithm));
    auto [it, inserted] = index.emplace(key, rows.size());
    if (inserted) {
      SummaryRow row;
      row.scenario = at(c_scenario);
      row.sweep = at(c_sweep);
      row.sweep_value = at(c_value);
      row.algorithm = at(c_algorithm);
      row.s2 = s2;
      row.uavs = uavs;
      rows.push_back(row);
      tc.emplace_back();
      tm.emplace_back();
      btc.emplace_back();
      btm.emplace_back();
    }
    SummaryRow& row = rows[it->second];
    ++row.runs;
    if (at(c_complete) != "1") ++row.incomplete;
    if (!at(c_tc).empty()) tc[it->second].push_back(csv_seconds(at(c_tc), source, line, "T_c"));
    if (!at(c_tm).empty()) tm[it->second].push_back(csv_seconds(at(c_tm), source, line, "T_m"));
    if (c_btc >= 0 && !at(c_btc).empty())
      btc[it->second].push_back(csv_seconds(at(c_btc), source, line, "bound_T_c"));
    if (c_btm >= 0 && !at(c_btm).empty())
      btm[it->second].push_back(csv_seconds(at(c_btm), source, line, "bound_T_m"));
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].t_c = stats(tc[i]);
    rows[i].t_m = stats(tm[i]);
    rows[i].bound_t_c = stats(btc[i]);
    rows[i].bound_t_m = stats(btm[i]);
  }
  return rows;
}

std::string summary_csv(const std::vector<SummaryRow>& rows) {
  std::string out =
      csv_line({"scenario",       "sweep",      "sweep_value", "s2",         "uavs",
                "algorithm",      "runs",       "incomplete",  "T_c_count",  "T_c_mean",
                "T_c_std",        "T_m_count",  "T_m_mean",    "T_m_std",    "bound_T_c_mean",
                "bound_T_m_mean", "T_c_ci_low", "T_c_ci_high", "T_m_ci_low", "T_m_ci_high"}) +
      "\n";
  auto number = [](const TimeStats& t, double v) {
    return t.count == 0 ? std::string() : fmt::format("{:.3f}", v);
  };
  for (const auto& r : rows) {
    out += csv_line({r.scenario,
                     r.sweep,
                     r.sweep_value,
                     std::to_string(r.s2),
                     std::to_string(r.uavs),
                     r.algorithm,
                     std::to_string(r.runs),
                     std::to_string(r.incomplete),
                     std::to_string(r.t_c.count),
                     number(r.t_c, r.t_c.mean),
                     number(r.t_c, r.t_c.std),
                     std::to_string(r.t_m.count),
                     number(r.t_m, r.t_m.mean),
                     number(r.t_m, r.t_m.std),
                     number(r.bound_t_c, r.bound_t_c.mean),
                     number(r.bound_t_m, r.bound_t_m.mean),
                     number(r.t_c, r.t_c.ci_low),
                     number(r.t_c, r.t_c.ci_high),
                     number(r.t_m, r.t_m.ci_low),
                     number(r.t_m, r.t_m.ci_high)}) +
           "\n";
  }
  return out;
}

std::string summary_markdown(const std::vector<SummaryRow>& rows) {
  // One group per plain scenario and one per sweep (all its values in one table, not one
  // one-row table per value).
  auto group_of = [](const SummaryRow& r) { return r.sweep.empty() ? r.scenario : r.sweep; };
  std::vector<std::pair<std::string, bool>> groups;  // (name, is a sweep)
  std::vector<std::string> algorithms;
  for (const auto& r : rows) {
    const std::pair<std::string, bool> g{group_of(r), !r.sweep.empty()};
    if (std::find(groups.begin(), groups.end(), g) == groups.end()) groups.push_back(g);
    if (std::find(algorithms.begin(), algorithms.end(), r.algorithm) == algorithms.end()) {
      algorithms.push_back(r.algorithm);
    }
  }
  std::string out;
  for (const auto& [group, is_sweep] : groups) {
    // Rows of the table: (swept value, s2, n) in order of appearance.
    using Key = std::tuple<std::string, int, int>;
    std::vector<Key> params;
    std::map<std::pair<Key, std::string>, const SummaryRow*> cell;
    int runs = 0;
    for (const auto& r : rows) {
      if (group_of(r) != group || r.sweep.empty() == is_sweep) continue;
      const Key p{is_sweep ? r.sweep_value : std::string(), r.s2, r.uavs};
      if (std::find(params.begin(), params.end(), p) == params.end()) params.push_back(p);
      cell[{p, r.algorithm}] = &r;
      runs = std::max(runs, r.runs);
    }
    bool any_bound = false;
    for (const auto& [key, r] : cell) any_bound = any_bound || r->bound_t_c.count > 0;
    for (const bool mission : {false, true}) {
      out += fmt::format("### {}{} — {} (s), mean ± std over {}{}\n\n", is_sweep ? "sweep of " : "",
                         group, mission ? "T_m" : "T_c", plural(runs, "instance"),
                         any_bound ? " (×: the mean over the lower bound's)" : "");
      std::vector<std::vector<std::string>> t;
      std::vector<std::string> header;
      if (is_sweep) header.push_back(group);
      header.insert(header.end(), {"s2", "n"});
      header.insert(header.end(), algorithms.begin(), algorithms.end());
      if (any_bound) header.push_back("lower bound");
      t.push_back(header);
      for (const auto& p : params) {
        std::vector<std::string> line;
        if (is_sweep) line.push_back(std::get<0>(p));
        line.push_back(std::to_string(std::get<1>(p)));
        line.push_back(std::to_string(std::get<2>(p)));
        // The bound depends on the instance only: every algorithm's rows hold the same seeds.
        double bound = 0;
        for (const auto& a : algorithms) {
          auto it = cell.find({p, a});
          if (it == cell.end()) continue;
          const TimeStats& b = mission ? it->second->bound_t_m : it->second->bound_t_c;
          if (b.count > 0) bound = b.mean;
          break;
        }
        for (const auto& a : algorithms) {
          auto it = cell.find({p, a});
          if (it == cell.end()) {
            line.push_back("");
            continue;
          }
          const SummaryRow& r = *it->second;
          const TimeStats& time = mission ? r.t_m : r.t_c;
          std::string text = mean_std(time);
          if (bound > 0 && time.count > 0) text += fmt::format(" (×{:.2f})", time.mean / bound);
          if (r.incomplete > 0) text += fmt::format(" [{} incomplete]", r.incomplete);
          line.push_back(text);
        }
        if (any_bound) line.push_back(bound > 0 ? fmt::format("{:.1f}", bound) : std::string());
        t.push_back(line);
      }
      out += table(t) + "\n";
    }
  }
  return out;
}

}  // namespace hullinspect::experiment
