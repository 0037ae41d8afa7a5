// hullinspect report: tables (Markdown, CSV) and figures (PNG, PDF) from an experiment's results.

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <string_view>

#include "experiment_commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/core/plural.hpp"
#include "hullinspect/experiment/build_data.hpp"
#include "hullinspect/experiment/manifest.hpp"
#include "hullinspect/experiment/paired.hpp"
#include "hullinspect/experiment/results_dir.hpp"
#include "hullinspect/experiment/summary.hpp"
#include "hullinspect/io/atomic_file.hpp"
#include "hullinspect/io/bounded_read.hpp"
#include "hullinspect/io/output_set.hpp"
#include "subprocess.hpp"

namespace hullinspect::cli {

namespace {

namespace fs = std::filesystem;

struct ReportArgs {
  std::string results;
  std::string out;
  bool no_figures = false;
  std::string python;
  std::vector<std::string> planners;  // compared and drawn, in this order (empty: all)
  std::vector<std::string> labels;    // ALGORITHM=LABEL for the figures
  std::vector<std::string> formats = {"png", "pdf"};
  int dpi = 150;
};

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ",") + i;
  return out;
}

std::string default_python() {
  const char* env = std::getenv("HULLINSPECT_PYTHON");
  return env != nullptr && *env != '\0' ? env : "/usr/bin/python3";
}

/// Figures from an earlier report of this directory (the new set may differ).
void remove_old_figures(const fs::path& dir) {
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string ext = entry.path().extension().string();
    if ((name.starts_with("fig6_") || name.starts_with("fig7_") || name.starts_with("fig8_")) &&
        (ext == ".png" || ext == ".pdf" || ext == ".svg")) {
      fs::remove(entry.path(), ec);
    }
  }
}

std::vector<std::string> figure_stems(const fs::path& dir, const std::string& format) {
  std::vector<std::string> stems;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().extension() == "." + format) stems.push_back(entry.path().stem().string());
  }
  std::sort(stems.begin(), stems.end());
  return stems;
}

void draw_figures(const ReportArgs& a, const fs::path& out) {
  const fs::path figures = out / "figures";
  fs::create_directories(figures);
  remove_old_figures(figures);
  const fs::path script = out / "plot_report.py";
  io::write_file_atomic(script, experiment::embedded_plot_script());
  const int status = run_process({a.python, script.string(), "--results", a.results, "--summary",
                                  (out / "summary.csv").string(), "--out", figures.string(),
                                  "--planners", joined(a.planners), "--labels", joined(a.labels),
                                  "--format", joined(a.formats), "--dpi", std::to_string(a.dpi)});
  if (status != 0) {
    throw Error(fmt::format(
        "plotting failed: {} {} exited with status {} (is Debian's python3-matplotlib installed? "
        "run scripts/setup, or pass --no-figures)",
        a.python, script.string(), status));
  }
}

/// The caption of a figure drawn by plot_report.py (the figures carry no titles), from its name.
std::string figure_caption(const std::string& name, std::size_t instances) {
  const std::string over = plural(static_cast<long long>(instances), "instance");
  const auto after = [&](std::string_view prefix) { return name.substr(prefix.size()); };
  if (name.starts_with("fig6_")) {
    return fmt::format(
        "Scenario {}: inspection time T_c (top) and mission time T_m (bottom), mean over {} with "
        "its 95 % bootstrap interval, by fleet size n, one column per s2; \"k inc.\" counts "
        "missions stopped by the time limit.",
        after("fig6_"), over);
  }
  if (name.starts_with("fig7_")) {
    const std::string rest = after("fig7_");
    const auto n = rest.rfind("_n");
    return fmt::format(
        "Scenario {}, n = {}: mean c(t) (top) and m(t) (bottom) over {} with a ±1 standard "
        "deviation band, one column per s2.",
        rest.substr(0, n), n == std::string::npos ? "?" : rest.substr(n + 2), over);
  }
  return fmt::format(
      "{}: mean c(t) over {} under each single-parameter sweep (line style = swept value) and in "
      "each plain scenario, colour = algorithm, one time axis for all panels.",
      name, over);
}

std::string report_markdown(const nlohmann::json& m, const ReportArgs& a, const std::string& tables,
                            const std::string& paired, const std::vector<std::string>& figures) {
  const auto& config = m.at("config");
  std::string md = fmt::format("# Experiment report: {}\n\n", config.value("name", "?"));
  if (!config.value("description", "").empty()) md += config.value("description", "") + "\n\n";
  md += fmt::format("- Results: `{}` — status {}, {} of {}, {} per cell\n", a.results,
                    m.value("status", "?"), m.value("runs_done", 0),
                    plural(m.value("runs_total", 0), "run"),
                    plural(static_cast<long long>(config.at("seeds").size()), "instance"));
  md += fmt::format("- Config: `{}` (fingerprint {}); hullinspect {} (git {})\n",
                    m.value("config_source", "?"), m.value("fingerprint", "?"),
                    m.value("version", "?"), m.value("git_revision", "unknown"));
  md += fmt::format("- Ran from {} to {}\n", m.value("started", "?"), m.value("finished", "?"));
  md +=
      "- Times in seconds (one step = 1 s). Each cell gives the mean ± sample standard deviation "
      "over the missions that reached the time; \"[k incomplete]\" counts missions stopped by the "
      "time limit, which are never counted as a number.\n\n";
  md += paired;
  md += "## Tables\n\nAlso in `summary.csv`; the paired differences in `paired.csv`.\n\n" + tables;
  if (!figures.empty()) {
    const auto& first = a.formats.front();
    // Name only the kinds of figure that were drawn (fig8 needs sweeps).
    std::vector<std::string> kinds;
    for (const auto& kind : {std::pair{"fig6_", "Fig. 6-style bars (`fig6_*`)"},
                             std::pair{"fig7_", "Fig. 7-style curves (`fig7_*`)"},
                             std::pair{"fig8_", "Fig. 8-style sweeps (`fig8_*`)"}}) {
      // Not a structured binding: clang 14 (the asan preset) cannot capture one in a lambda.
      const std::string_view prefix = kind.first;
      if (std::any_of(figures.begin(), figures.end(),
                      [&](const std::string& f) { return f.starts_with(prefix); })) {
        kinds.emplace_back(kind.second);
      }
    }
    std::string list;
    for (std::size_t i = 0; i < kinds.size(); ++i) {
      list += (i == 0 ? "" : i + 1 == kinds.size() ? " and " : ", ") + kinds[i];
    }
    md += fmt::format(
        "## Figures\n\n{}, as {}. Redraw them with `/usr/bin/python3 plot_report.py`.\n\n", list,
        joined(a.formats));
    for (const auto& f : figures) {
      md += fmt::format("### {}\n\n{}\n\n", f, figure_caption(f, config.at("seeds").size()));
      if (first == "pdf") {
        md += fmt::format("[{}](figures/{}.pdf)\n\n", f, f);
      } else {
        md += fmt::format("![{}](figures/{}.{})\n\n", f, f, first);
      }
      for (const auto& other : a.formats) {
        if (other != first) md += fmt::format("[{}](figures/{}.{}) ", other, f, other);
      }
      if (a.formats.size() > 1) md += "\n\n";
    }
  }
  return md;
}

// The Python that draws the figures must exist before anything is written.
void check_python(const std::string& python) {
  const bool has_slash = python.find('/') != std::string::npos;
  if (has_slash) {
    if (::access(python.c_str(), X_OK) == 0 && !fs::is_directory(python)) return;
  } else if (const char* path = std::getenv("PATH"); path != nullptr) {
    std::string dirs = path;
    std::size_t start = 0;
    while (start <= dirs.size()) {
      const std::size_t end = std::min(dirs.find(':', start), dirs.size());
      const fs::path candidate = fs::path(dirs.substr(start, end - start)) / python;
      if (::access(candidate.c_str(), X_OK) == 0 && !fs::is_directory(candidate)) return;
      start = end + 1;
    }
  }
  throw ParameterError("python", fmt::format("'{}' is not an executable program (install "
                                             "python3-matplotlib with scripts/setup, or pass "
                                             "--no-figures)",
                                             escape_for_message(python, 200)));
}

int run(const ReportArgs& a) {
  const fs::path results(a.results);
  const fs::path out(a.out);
  io::OutputSet outputs;
  outputs.add_input(results / experiment::kRunsFile, "results");
  outputs.add_output_dir(out, "out");
  outputs.check();
  if (!a.no_figures) check_python(a.python);
  const auto manifest = experiment::read_manifest(results);
  for (const char* file : {experiment::kRunsFile, experiment::kCurvesFile}) {
    if (!fs::exists(results / file)) {
      throw InputError((results / file).string(), 0,
                       "not found: the experiment has not finished (continue it with --resume, or "
                       "merge its shards first)");
    }
  }
  const auto runs_path = (results / experiment::kRunsFile).string();
  const auto runs =
      experiment::parse_csv(io::read_file(runs_path, std::size_t{16} << 30), runs_path);
  const auto rows = experiment::summarize_runs(runs, runs_path);
  experiment::PairedOptions paired_options;
  paired_options.algorithms = a.planners;
  const auto analysis = experiment::analyse_pairs(runs, runs_path, paired_options);
  for (const auto& l : a.labels) {
    const auto eq = l.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == l.size()) {
      throw ParameterError("labels", fmt::format("'{}' is not ALGORITHM=LABEL", l));
    }
    const auto name = l.substr(0, eq);
    if (std::find(analysis.algorithms.begin(), analysis.algorithms.end(), name) ==
        analysis.algorithms.end()) {
      throw ParameterError("labels", fmt::format("'{}' is not an algorithm of the report", name));
    }
  }
  const auto claims = experiment::check_paper_claims(analysis);
  if (manifest.value("shard", "1/1") != "1/1") {
    std::cerr << fmt::format(
        "hullinspect: {} holds shard {} only: merge the shards for the whole "
        "experiment\n",
        a.results, manifest.value("shard", "?"));
  }
  if (manifest.value("status", "") != "complete") {
    std::cerr << fmt::format(
        "hullinspect: {} has status '{}': the report covers the {} runs found\n", a.results,
        manifest.value("status", "?"), runs.rows.size());
  }
  fs::create_directories(out);
  const std::string tables = experiment::summary_markdown(rows);
  io::write_file_atomic(out / "summary.csv", experiment::summary_csv(rows));
  io::write_file_atomic(out / "summary.md", tables);
  io::write_file_atomic(out / "paired.csv", experiment::paired_csv(analysis));
  if (!a.no_figures) draw_figures(a, out);
  const auto figures =
      !a.no_figures ? figure_stems(out / "figures", a.formats.front()) : std::vector<std::string>{};
  io::write_file_atomic(
      out / "report.md",
      report_markdown(manifest, a, tables, experiment::paired_markdown(analysis, claims), figures));
  std::cout << tables;
  std::cout << "\nThe paper's claims (details and paired differences in report.md):\n";
  for (const auto& c : claims) std::cout << fmt::format("  {}: {}\n", c.id, c.verdict);
  std::cout << fmt::format("report: {} ({}; {} as {})\n", (out / "report.md").string(),
                           plural(static_cast<long long>(rows.size()), "cell"),
                           plural(static_cast<long long>(figures.size()), "figure"),
                           joined(a.formats));
  return 0;
}

}  // namespace

void add_report_command(CLI::App& app, CommandAction& action) {
  auto args = std::make_shared<ReportArgs>();
  args->python = default_python();
  CLI::App* cmd =
      app.add_subcommand("report", "Write tables and figures for an experiment's results");
  cmd->footer(
      "Writes REPORTDIR/report.md, summary.md, summary.csv, plot_report.py and figures/*.png|pdf;\n"
      "prints the summary tables. Example: hullinspect report results/quick --out report/quick");
  cmd->add_option("results", args->results, "Results directory of `hullinspect experiment`/`merge`")
      ->required()
      ->type_name("DIR");
  cmd->add_option("--out,-o", args->out, "Directory for the report (created; files replaced)")
      ->required()
      ->type_name("REPORTDIR");
  cmd->add_flag("--no-figures", args->no_figures, "Only the tables (no Python needed)");
  cmd->add_option("--python", args->python,
                  "Python with matplotlib (default: $HULLINSPECT_PYTHON or /usr/bin/python3)")
      ->type_name("PATH");
  cmd->add_option("--planners", args->planners,
                  "Algorithms to compare and draw, in this order (default: all in the results)")
      ->delimiter(',')
      ->type_name("A,B,...");
  cmd->add_option("--labels", args->labels, "Legend labels for the figures, ALGORITHM=LABEL")
      ->delimiter(',')
      ->type_name("A=LABEL,...");
  cmd->add_option("--format", args->formats, "Figure file types: png, pdf, svg")
      ->delimiter(',')
      ->check(CLI::IsMember({"png", "pdf", "svg"}))
      ->capture_default_str()
      ->type_name("png,pdf");
  cmd->add_option("--dpi", args->dpi, "Resolution of PNG figures")
      ->check(CLI::Range(30, 1200))
      ->capture_default_str();
  cmd->callback([args, &action] { action = [args] { return run(*args); }; });
}

}  // namespace hullinspect::cli
