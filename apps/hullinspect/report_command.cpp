// hullinspect report: tables (Markdown, CSV) and figures (PNG, PDF) from an experiment's results.

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <memory>

#include "experiment_commands.hpp"
#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/experiment/build_data.hpp"
#include "hullinspect/experiment/manifest.hpp"
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
};

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
        (ext == ".png" || ext == ".pdf")) {
      fs::remove(entry.path(), ec);
    }
  }
}

std::vector<std::string> figure_stems(const fs::path& dir) {
  std::vector<std::string> stems;
  std::error_code ec;
  for (const auto& entry : fs::directory_iterator(dir, ec)) {
    if (entry.path().extension() == ".png") stems.push_back(entry.path().stem().string());
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
                                  (out / "summary.csv").string(), "--out", figures.string()});
  if (status != 0) {
    throw Error(fmt::format(
        "plotting failed: {} {} exited with status {} (is Debian's python3-matplotlib installed? "
        "run scripts/setup, or pass --no-figures)",
        a.python, script.string(), status));
  }
}

std::string report_markdown(const nlohmann::json& m, const ReportArgs& a, const std::string& tables,
                            const std::vector<std::string>& figures) {
  const auto& config = m.at("config");
  std::string md = fmt::format("# Experiment report: {}\n\n", config.value("name", "?"));
  if (!config.value("description", "").empty()) md += config.value("description", "") + "\n\n";
  md += fmt::format("- Results: `{}` — status {}, {} of {} runs, {} instances per cell\n",
                    a.results, m.value("status", "?"), m.value("runs_done", 0),
                    m.value("runs_total", 0), config.at("seeds").size());
  md += fmt::format("- Config: `{}` (fingerprint {}); hullinspect {} (git {})\n",
                    m.value("config_source", "?"), m.value("fingerprint", "?"),
                    m.value("version", "?"), m.value("git_revision", "unknown"));
  md += fmt::format("- Ran from {} to {}\n", m.value("started", "?"), m.value("finished", "?"));
  md +=
      "- Times in seconds (one step = 1 s). Each cell gives the mean ± sample standard deviation "
      "over the missions that reached the time; \"[k incomplete]\" counts missions stopped by the "
      "time limit, which are never counted as a number.\n\n";
  md += "## Tables\n\nAlso in `summary.csv`.\n\n" + tables;
  if (!figures.empty()) {
    md +=
        "## Figures\n\nFig. 6-style bars (`fig6_*`), Fig. 7-style curves (`fig7_*`) and Fig. "
        "8-style sweeps (`fig8_*`); each also as PDF. Redraw them with `/usr/bin/python3 "
        "plot_report.py`.\n\n";
    for (const auto& f : figures) {
      md += fmt::format("### {}\n\n![{}](figures/{}.png)\n\n[PDF](figures/{}.pdf)\n\n", f, f, f, f);
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
  const auto runs = experiment::parse_csv(io::read_file(runs_path, std::size_t{16} << 30), runs_path);
  const auto rows = experiment::summarize_runs(runs, runs_path);
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
  if (!a.no_figures) draw_figures(a, out);
  const auto figures = !a.no_figures ? figure_stems(out / "figures") : std::vector<std::string>{};
  io::write_file_atomic(out / "report.md", report_markdown(manifest, a, tables, figures));
  std::cout << tables;
  std::cout << fmt::format("report: {} ({} cells; {} figures as PNG and PDF)\n",
                           (out / "report.md").string(), rows.size(), figures.size());
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
  cmd->callback([args, &action] { action = [args] { return run(*args); }; });
}

}  // namespace hullinspect::cli
