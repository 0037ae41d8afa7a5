// curves.csv from the per-run samples. Values are summed in canonical run order, so the result is
// the same whether the runs came from one process, a resumed one or merged shards.

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <string>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/journal.hpp"
#include "hullinspect/experiment/results_dir.hpp"

namespace hullinspect::experiment {

namespace {

int header_index(const std::vector<std::string>& header, const std::string& name) {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  throw LogicError(fmt::format("runs.csv has no column '{}'", name));
}

long long to_integer(std::string_view s) {
  long long v = 0;
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size()) {
    throw InputError(kSamplesFile, 0, fmt::format("'{}' is not an integer", s));
  }
  return v;
}

/// Parses "id,a,b,c" into its integers after the id.
void sample_values(std::string_view line, std::vector<long long>& out) {
  out.clear();
  std::size_t pos = line.find(',');
  while (pos != std::string_view::npos) {
    const std::size_t next = line.find(',', pos + 1);
    out.push_back(to_integer(line.substr(pos + 1, next == std::string_view::npos
                                                      ? std::string_view::npos
                                                      : next - pos - 1)));
    pos = next;
  }
}

std::string format_stat(double v) { return fmt::format("{:.4f}", v); }

}  // namespace

std::string curves_csv(const ExperimentPlan& plan, const OrderedLines& lines) {
  const auto& config = plan.config();
  const auto times = config.curve.times();
  const std::size_t k = times.size();
  const auto header = runs_header();
  const int col_cell = header_index(header, "cell_id");
  const int col_hull = header_index(header, "hull_cells");
  const int col_corroded = header_index(header, "corroded_cells");

  std::string out = csv_line({"cell_id", "scenario", "sweep", "sweep_value", "algorithm", "s2",
                              "uavs", "t", "runs", "c_mean", "c_std", "m_mean", "m_std"}) +
                    "\n";
  // Runs are in canonical order, so each cell's runs are contiguous.
  std::vector<std::vector<double>> c_values;  // per run: c at each time
  std::vector<std::vector<double>> m_values;
  std::vector<long long> samples;
  std::size_t i = 0;
  while (i < lines.runs.size()) {
    const auto first = split_csv_line(lines.runs[i]);
    const std::string cell_id = (*first)[static_cast<std::size_t>(col_cell)];
    c_values.clear();
    m_values.clear();
    std::size_t j = i;
    for (; j < lines.runs.size(); ++j) {
      const auto fields = split_csv_line(lines.runs[j]);
      if ((*fields)[static_cast<std::size_t>(col_cell)] != cell_id) break;
      const long long hull = to_integer((*fields)[static_cast<std::size_t>(col_hull)]);
      const long long corroded = to_integer((*fields)[static_cast<std::size_t>(col_corroded)]);
      sample_values(lines.samples[j], samples);
      if (samples.size() != 2 * k || hull <= 0) {
        throw InputError(kSamplesFile, 0, fmt::format("run {} has malformed samples", line_id(lines.runs[j])));
      }
      std::vector<double> c(k);
      std::vector<double> m(k);
      for (std::size_t t = 0; t < k; ++t) {
        c[t] = corroded == 0 ? 100.0 : 100.0 * static_cast<double>(samples[t]) / static_cast<double>(corroded);
        m[t] = 100.0 * static_cast<double>(samples[k + t]) / static_cast<double>(hull);
      }
      c_values.push_back(std::move(c));
      m_values.push_back(std::move(m));
    }
    // Cell labels from the plan (the cell id identifies the cell).
    const Cell* cell = &plan.cells()[static_cast<std::size_t>(
        plan.runs()[static_cast<std::size_t>(plan.run_position(std::string(line_id(lines.runs[i]))))].cell)];
    const auto& s = config.scenarios[static_cast<std::size_t>(cell->scenario)];
    const auto& a = config.algorithms[static_cast<std::size_t>(cell->algorithm)];
    const std::string prefix = csv_line(
        {cell_id, s.name, s.sweep, s.sweep_value, a.label,
         std::to_string(config.s2[static_cast<std::size_t>(cell->s2)]),
         std::to_string(config.uavs[static_cast<std::size_t>(cell->uavs)])});
    const std::size_t n = c_values.size();
    for (std::size_t t = 0; t < k; ++t) {
      auto stats = [&](const std::vector<std::vector<double>>& v) {
        double sum = 0;
        for (const auto& run : v) sum += run[t];
        const double mean = sum / static_cast<double>(n);
        if (n < 2) return std::pair(format_stat(mean), std::string());
        double sq = 0;
        for (const auto& run : v) sq += (run[t] - mean) * (run[t] - mean);
        return std::pair(format_stat(mean), format_stat(std::sqrt(sq / static_cast<double>(n - 1))));
      };
      const auto [c_mean, c_std] = stats(c_values);
      const auto [m_mean, m_std] = stats(m_values);
      out += fmt::format("{},{},{},{},{},{},{}\n", prefix, times[t], n, c_mean, c_std, m_mean, m_std);
    }
    i = j;
  }
  return out;
}

}  // namespace hullinspect::experiment
