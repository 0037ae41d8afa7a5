#include "hullinspect/experiment/summary.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <map>
#include <optional>
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

// The bounds of the missions that reached a time: the ratio "(×r)" divides the mean time by the
// mean bound of the same missions, not of every mission of the cell.
struct BoundOfReached {
  double sum = 0;
  double time_sum = 0;
  int count = 0;
  void add(std::optional<double> time, std::optional<double> bound) {
    if (!time || !bound) return;
    sum += *bound;
    time_sum += *time;
    ++count;
  }
  double mean_bound() const { return count == 0 ? 0 : sum / count; }
  double mean_time() const { return count == 0 ? 0 : time_sum / count; }
};

struct Paired {
  BoundOfReached t_c, t_m;
};

struct SortieColumns {
  int sorties, flight, crashes, battery;
};

// A run that flew sorties (one with launch sites) adds its per-UAV sorties and flight seconds
// (summed here, divided by the runs at the end), its smallest battery margin and its crashes.
template <class At>
void add_sorties(SummaryRow& row, const At& at, const std::string& source, int line,
                 const SortieColumns& c) {
  const int uavs = std::max(row.uavs, 1);
  const int sorties = csv_int(at(c.sorties), source, line, "sorties");
  if (sorties == 0) return;
  auto& s = row.sorties;
  ++s.runs;
  s.per_uav += static_cast<double>(sorties) / uavs;
  s.flight_s_per_uav += csv_seconds(at(c.flight), source, line, "flight_s") / uavs;
  s.battery_crashes += csv_int(at(c.crashes), source, line, "battery_crashes");
  if (!at(c.battery).empty()) {
    const double margin = csv_seconds(at(c.battery), source, line, "min_battery_s");
    s.min_battery_s = std::min(s.min_battery_s.value_or(margin), margin);
  }
}

using TableKey = std::tuple<std::string, int, int>;  // (swept value, s2, n)

// The group's sorties, one row per (swept value, s2, n, algorithm) that flew any; empty when none.
std::string sorties_table(
    const std::string& group, bool is_sweep, const std::vector<TableKey>& params,
    const std::vector<std::string>& algorithms,
    const std::map<std::pair<TableKey, std::string>, const SummaryRow*>& cell) {
  std::vector<std::vector<std::string>> t;
  std::vector<std::string> header;
  if (is_sweep) header.push_back(group);
  header.insert(header.end(),
                {"s2", "n", "algorithm", "runs", "sorties per UAV", "flight per UAV (s)",
                 "smallest battery margin (s)", "battery crashes"});
  t.push_back(header);
  for (const auto& p : params) {
    for (const auto& a : algorithms) {
      const auto it = cell.find({p, a});
      if (it == cell.end() || it->second->sorties.runs == 0) continue;
      const SummaryRow::Sorties& s = it->second->sorties;
      std::vector<std::string> line;
      if (is_sweep) line.push_back(std::get<0>(p));
      line.insert(line.end(),
                  {std::to_string(std::get<1>(p)), std::to_string(std::get<2>(p)), a,
                   std::to_string(s.runs), fmt::format("{:.2f}", s.per_uav),
                   fmt::format("{:.1f}", s.flight_s_per_uav),
                   s.min_battery_s ? fmt::format("{:g}", *s.min_battery_s) : "unlimited",
                   std::to_string(s.battery_crashes)});
      t.push_back(std::move(line));
    }
  }
  if (t.size() == 1) return "";
  return fmt::format(
             "### {}{} — sorties: per UAV the mean sorties and flight time over the runs, the "
             "smallest battery margin flown by any UAV, the crashes\n\n",
             is_sweep ? "sweep of " : "", group) +
         table(t) + "\n";
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
  // Sorties: runs.csv files written before batteries lack these columns.
  const int c_sorties = runs.find_column("sorties");
  const int c_flight = runs.find_column("flight_s");
  const int c_crashes = runs.find_column("battery_crashes");
  const int c_battery = runs.find_column("min_battery_s");
  const bool has_sorties = c_sorties >= 0 && c_flight >= 0 && c_crashes >= 0 && c_battery >= 0;

  std::vector<SummaryRow> rows;
  std::vector<std::vector<double>> tc, tm, btc, btm;
  std::vector<Paired> paired;
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
      paired.emplace_back();
    }
    const std::size_t i = it->second;
    SummaryRow& row = rows[i];
    ++row.runs;
    if (at(c_complete) != "1") ++row.incomplete;
    const auto time = [&](int c, const char* name) -> std::optional<double> {
      if (c < 0 || at(c).empty()) return std::nullopt;
      return csv_seconds(at(c), source, line, name);
    };
    const auto t_c = time(c_tc, "T_c");
    const auto t_m = time(c_tm, "T_m");
    const auto b_c = time(c_btc, "bound_T_c");
    const auto b_m = time(c_btm, "bound_T_m");
    if (t_c) tc[i].push_back(*t_c);
    if (t_m) tm[i].push_back(*t_m);
    if (b_c) btc[i].push_back(*b_c);
    if (b_m) btm[i].push_back(*b_m);
    paired[i].t_c.add(t_c, b_c);
    paired[i].t_m.add(t_m, b_m);
    if (has_sorties)
      add_sorties(row, at, source, line, {c_sorties, c_flight, c_crashes, c_battery});
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].t_c = stats(tc[i]);
    rows[i].t_m = stats(tm[i]);
    rows[i].bound_t_c = stats(btc[i]);
    rows[i].bound_t_m = stats(btm[i]);
    rows[i].t_c_bound = paired[i].t_c.mean_bound();
    rows[i].t_m_bound = paired[i].t_m.mean_bound();
    rows[i].t_c_paired = paired[i].t_c.mean_time();
    rows[i].t_m_paired = paired[i].t_m.mean_time();
    auto& s = rows[i].sorties;
    if (s.runs > 0) {
      s.per_uav /= s.runs;
      s.flight_s_per_uav /= s.runs;
    }
  }
  return rows;
}

std::string summary_csv(const std::vector<SummaryRow>& rows) {
  std::string out = csv_line({"scenario",
                              "sweep",
                              "sweep_value",
                              "s2",
                              "uavs",
                              "algorithm",
                              "runs",
                              "incomplete",
                              "T_c_count",
                              "T_c_mean",
                              "T_c_std",
                              "T_m_count",
                              "T_m_mean",
                              "T_m_std",
                              "bound_T_c_mean",
                              "bound_T_m_mean",
                              "T_c_ci_low",
                              "T_c_ci_high",
                              "T_m_ci_low",
                              "T_m_ci_high",
                              "sortie_runs",
                              "sorties_per_uav",
                              "flight_s_per_uav",
                              "min_battery_s",
                              "battery_crashes"}) +
                    "\n";
  auto number = [](const TimeStats& t, double v) {
    return t.count == 0 ? std::string() : fmt::format("{:.3f}", v);
  };
  for (const auto& r : rows) {
    // Empty for a cell that flew no sorties (no launch sites).
    auto sortie_number = [&](double v) {
      return r.sorties.runs == 0 ? std::string() : fmt::format("{:.3f}", v);
    };
    out += csv_line(
               {r.scenario,
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
                number(r.t_m, r.t_m.ci_high),
                std::to_string(r.sorties.runs),
                sortie_number(r.sorties.per_uav),
                sortie_number(r.sorties.flight_s_per_uav),
                r.sorties.min_battery_s ? fmt::format("{:.3f}", *r.sorties.min_battery_s)
                                        : std::string(),
                r.sorties.runs == 0 ? std::string() : std::to_string(r.sorties.battery_crashes)}) +
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
    using Key = TableKey;
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
      out += fmt::format(
          "### {}{} — {} (s), mean ± std over {}{}\n\n", is_sweep ? "sweep of " : "", group,
          mission ? "T_m" : "T_c", plural(runs, "instance"),
          any_bound ? " (×: the mean over the mean lower bound of the same missions)" : "");
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
          const double paired_bound = mission ? r.t_m_bound : r.t_c_bound;
          const double paired_time = mission ? r.t_m_paired : r.t_c_paired;
          if (bound > 0 && time.count > 0 && paired_bound > 0) {
            text += fmt::format(" (×{:.2f})",
                                (paired_time > 0 ? paired_time : time.mean) / paired_bound);
          }
          if (r.incomplete > 0) text += fmt::format(" [{} incomplete]", r.incomplete);
          line.push_back(text);
        }
        if (any_bound) line.push_back(bound > 0 ? fmt::format("{:.1f}", bound) : std::string());
        t.push_back(line);
      }
      out += table(t) + "\n";
    }
    out += sorties_table(group, is_sweep, params, algorithms, cell);
  }
  return out;
}

}  // namespace hullinspect::experiment
