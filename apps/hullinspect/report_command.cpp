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
#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/manifest.hpp"
#include "hullinspect/experiment/paired.hpp"
#include "hullinspect/experiment/results_dir.hpp"
#include "hullinspect/experiment/staged_dir.hpp"
#include "hullinspect/experiment/summary.hpp"
#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/files/output_set.hpp"
#include "number_options.hpp"
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
  bool partial = false;         // report an incomplete set of runs (flagged) instead of refusing
  double python_seconds = 600;  // the plotting child's time limit
};

/// The report's input: the validated rows of a finished results directory.
struct ReportInput {
  nlohmann::json manifest;
  experiment::CsvTable runs;
  int runs_total = 0;
  std::vector<std::string> missing;  // run ids of the plan with no row, in canonical order
};

/// Up to three run ids, then how many more.
std::string missing_list(const std::vector<std::string>& ids) {
  std::string out = "run";
  for (std::size_t i = 0; i < ids.size() && i < 3; ++i) out += (i == 0 ? " " : ", ") + ids[i];
  if (ids.size() > 3) out += fmt::format(" and {} more", ids.size() - 3);
  return out;
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& i : items) out += (out.empty() ? "" : ",") + i;
  return out;
}

std::string default_python() {
  const char* env = std::getenv("HULLINSPECT_PYTHON");
  return env != nullptr && *env != '\0' ? env : "/usr/bin/python3";
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

/// The Python's own messages, for a failure: its last line (a traceback ends with the error).
std::string last_line(const fs::path& log) {
  std::string text;
  try {
    text = io::read_file(log, std::size_t{1} << 20);
  } catch (const Error&) {
    return "";
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  const auto start = text.rfind('\n');
  return escape_for_message(start == std::string::npos ? text : text.substr(start + 1), 200);
}

/// Draws the figures into `staging`/figures with the script written to `staging`.
void draw_figures(const ReportArgs& a, const fs::path& staging) {
  const fs::path figures = staging / "figures";
  fs::create_directories(figures);
  const fs::path script = staging / "plot_report.py";
  io::write_file_atomic(script, experiment::embedded_plot_script());
  const fs::path log = staging / "plot_report.log";
  const auto r = run_process({a.python, script.string(), "--results", a.results, "--summary",
                              (staging / "summary.csv").string(), "--out", figures.string(),
                              "--planners", joined(a.planners), "--labels", joined(a.labels),
                              "--format", joined(a.formats), "--dpi", std::to_string(a.dpi)},
                             log, a.python_seconds);
  const std::string said = last_line(log);
  std::error_code ec;
  fs::remove(log, ec);
  if (r.timed_out) {
    throw Error(
        fmt::format("--python: plotting did not finish within {} s: {} was stopped (raise "
                    "--python-timeout, or pass --no-figures)",
                    a.python_seconds, escape_for_message(a.python, 200)));
  }
  if (r.status != 0) {
    throw Error(fmt::format(
        "--python: plotting failed: {} exited with status {}{} (is Debian's python3-matplotlib "
        "installed? run scripts/setup, or pass --no-figures)",
        escape_for_message(a.python, 200), r.status, said.empty() ? "" : ": " + said));
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

std::string report_markdown(const ReportInput& in, const ReportArgs& a, const std::string& tables,
                            const std::string& paired, const std::vector<std::string>& figures) {
  const auto& m = in.manifest;
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
  if (!in.missing.empty()) {
    md += fmt::format(
        "- **Partial**: {} of the experiment's {} missing ({}); every table and "
        "figure covers only the runs found\n",
        in.missing.size(), plural(in.runs_total, "run"), missing_list(in.missing));
  }
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

ReportInput read_results(const ReportArgs& a) {
  const fs::path results(a.results);
  ReportInput in;
  in.manifest = experiment::read_manifest(results);
  for (const char* file : {experiment::kRunsFile, experiment::kCurvesFile}) {
    if (!fs::exists(results / file)) {
      throw InputError((results / file).string(), 0,
                       "not found: the experiment has not finished (continue it with --resume, or "
                       "merge its shards first)");
    }
  }
  // Every row is checked against the experiment's plan, as --resume and merge check them.
  const auto plan = experiment::results_plan(results, in.manifest);
  const auto stored = experiment::read_stored_runs(results, plan, true);
  in.runs_total = static_cast<int>(plan.runs().size());
  for (const auto& run : plan.runs()) {
    if (!stored.records.contains(run.id)) in.missing.push_back(run.id);
  }
  if (!in.missing.empty() && !a.partial) {
    throw InputError((results / experiment::kRunsFile).string(), 0,
                     fmt::format("{} of the experiment's {} {} missing ({}): finish them with "
                                 "--resume or merge the shards, or pass --partial",
                                 in.missing.size(), plural(in.runs_total, "run"),
                                 in.missing.size() == 1 ? "is" : "are", missing_list(in.missing)));
  }
  const auto curves_path = (results / experiment::kCurvesFile).string();
  if (io::read_file(curves_path, std::size_t{16} << 30) !=
      experiment::curves_csv(plan, experiment::canonical_lines(plan, stored))) {
    throw InputError(curves_path, 0,
                     "does not match runs.csv and samples.csv (truncated or edited? merge the "
                     "directory into a new one to rebuild it)");
  }
  const auto runs_path = (results / experiment::kRunsFile).string();
  in.runs = experiment::parse_csv(io::read_file(runs_path, std::size_t{16} << 30), runs_path);
  return in;
}

int run_report(const ReportArgs& a) {
  const fs::path results(a.results);
  const fs::path out(a.out);
  io::OutputSet outputs;
  outputs.add_input(results / experiment::kRunsFile, "results");
  outputs.add_output_dir(out, "out");
  outputs.check();
  if (!a.no_figures) check_python(a.python);
  const ReportInput in = read_results(a);
  const auto rows = experiment::summarize_runs(in.runs, (results / experiment::kRunsFile).string());
  experiment::PairedOptions paired_options;
  paired_options.algorithms = a.planners;
  const auto analysis = experiment::analyse_pairs(
      in.runs, (results / experiment::kRunsFile).string(), paired_options);
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
  if (!in.missing.empty()) {
    std::cerr << fmt::format("hullinspect: {}: partial report: {} of the experiment's {} missing\n",
                             a.results, in.missing.size(), plural(in.runs_total, "run"));
  }
  // Everything is written into a staging directory and moved into --out only when all is written.
  experiment::StagedDir staged(out);
  const fs::path& stage = staged.path();
  const std::string tables = experiment::summary_markdown(rows);
  io::write_file_atomic(stage / "summary.csv", experiment::summary_csv(rows));
  io::write_file_atomic(stage / "summary.md", tables);
  io::write_file_atomic(stage / "paired.csv", experiment::paired_csv(analysis));
  InterruptGuard::check();
  if (!a.no_figures) draw_figures(a, stage);
  const auto figures = !a.no_figures ? figure_stems(stage / "figures", a.formats.front())
                                     : std::vector<std::string>{};
  io::write_file_atomic(
      stage / "report.md",
      report_markdown(in, a, tables, experiment::paired_markdown(analysis, claims), figures));
  InterruptGuard::check();
  staged.commit();
  std::cout << tables;
  std::cout << "\nThe paper's claims (details and paired differences in report.md):\n";
  for (const auto& c : claims) std::cout << fmt::format("  {}: {}\n", c.id, c.verdict);
  std::cout << fmt::format("report: {} ({}; {} as {})\n", (out / "report.md").string(),
                           plural(static_cast<long long>(rows.size()), "cell"),
                           plural(static_cast<long long>(figures.size()), "figure"),
                           joined(a.formats));
  return 0;
}

int run(const ReportArgs& a) {
  InterruptGuard guard;
  try {
    return run_report(a);
  } catch (const Interrupted& e) {
    // The staging directory is gone (unwound); end as the signal would have.
    InterruptGuard::die(e.signal());
  }
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
      ->check(integer_in(30, 1200))
      ->capture_default_str();
  cmd->add_flag("--partial", args->partial,
                "Report the runs found when some of the experiment's runs are missing (flagged in "
                "report.md); without it such results are refused");
  cmd->add_option("--python-timeout", args->python_seconds,
                  "Seconds the plotting may take before it is stopped")
      ->check(real_in(1, 86400))
      ->capture_default_str()
      ->type_name("SECONDS");
  cmd->callback([args, &action] { action = [args] { return run(*args); }; });
}

}  // namespace hullinspect::cli
