// Every input option of every command that writes files, against every output option of that
// command: an output that is the input (the same path, a symbolic link to it, a hard link to it,
// or, for an output directory, the input lying in it under a name the command writes) is refused
// with exit status 2 and one line, and nothing in the directory changes. The options come from
// each command's --help (every option whose value is a path); the test fails when an option
// appears there that the table below does not classify, so a new input option is walked too.

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/dir_snapshot.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

enum class Role { kInput, kOutputFile, kOutputDir };

struct Option {
  Role role;
  std::string fixture;    // inputs: the fixture file the option reads
  std::string dir_entry;  // output directories: a file the command writes into it
};

struct Command {
  std::vector<std::string> words;  // "hull", "import"
  std::vector<std::string> base;   // arguments every run gets (before the walked options)
  // Options (or positional names, as --help prints them) whose value is a path.
  std::map<std::string, Option> options;
};

const std::vector<std::string> kMission = {"-n", "1", "--s1", "1", "--s2", "3"};

std::vector<Command> commands() {
  const Option hull{Role::kInput, "hull.txt", ""};
  const Option mask{Role::kInput, "mask.txt", ""};
  const Option no_fly{Role::kInput, "nofly.txt", ""};
  const Option geo{Role::kInput, "geo.yaml", ""};
  const Option trace{Role::kInput, "trace.json", ""};
  const Option defects{Role::kInput, "defects.csv", ""};
  const Option out_file{Role::kOutputFile, "", ""};
  const Option export_dir{Role::kOutputDir, "", "uav0.csv"};
  std::vector<Command> all = {
      {{"run"},
       kMission,
       {{"--hull", hull},
        {"--prior", mask},
        {"--truth", mask},
        {"--prior-defects", defects},
        {"--truth-defects", defects},
        {"--no-fly", no_fly},
        {"--geo", geo},
        {"--trace", out_file},
        {"--html", out_file},
        {"--export", export_dir}}},
      {{"partition"},
       {"--uavs", "2"},
       {{"--hull", hull}, {"--no-fly", no_fly}, {"--out", out_file}}},
      {{"view"}, {}, {{"trace", trace}, {"--out", out_file}}},
      {{"export"}, {}, {{"trace", trace}, {"--geo", geo}, {"--out", export_dir}}},
      {{"hull", "import"}, {}, {{"MESH", {Role::kInput, "mesh.stl", ""}}, {"--out", out_file}}},
      {{"experiment"},
       {"--jobs", "1"},
       {{"--config", {Role::kInput, "config.yaml", ""}},
        {"--out", {Role::kOutputDir, "", "runs.csv"}}}},
  };
  // plan reads what run reads and writes what run writes, but no HTML replay; it writes the
  // export's pre-flight report.
  Command plan = all.front();
  plan.words = {"plan"};
  plan.options.erase("--html");
  plan.options["--report"] = {Role::kOutputDir, "", "preflight.json"};
  all.push_back(plan);
  return all;
}

// The path-valued options --help lists: type names FILE, DIR, TRACE, REPORTDIR, an option whose
// help says it writes ("Write the hull to NAME.json"), and every positional.
std::set<std::string> path_options(const std::vector<std::string>& words) {
  std::vector<std::string> args = words;
  args.push_back("--help");
  const CliResult r = run_cli(args);
  EXPECT_EQ(r.status, 0) << r.err;
  std::set<std::string> out;
  std::istringstream lines(r.out);
  std::string line;
  bool positionals = false;
  const std::regex option(
      R"(^\s+(?:-\w,)?(--[\w-]+) (?:(?:FILE|DIR|TRACE|REPORTDIR)\b.*|\S+( REQUIRED)?\s+Write .*))");
  const std::regex positional(R"(^\s+(\w+) \w+ REQUIRED.*)");
  std::smatch m;
  while (std::getline(lines, line)) {
    if (line.starts_with("Positionals:")) positionals = true;
    if (line.starts_with("Options:")) positionals = false;
    if (std::regex_match(line, m, option)) out.insert(m[1]);
    if (positionals && std::regex_match(line, m, positional)) out.insert(m[1]);
  }
  return out;
}

void put(const fs::path& p, const std::string& s) {
  fs::create_directories(p.parent_path());
  std::ofstream(p, std::ios::binary) << s;
}

class InputOutputWalk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fixtures_ = make_temp_dir("io-walk-fixtures");
    const fs::path f = fixtures_;
    put(f / "hull.txt", "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n");
    put(f / "mask.txt", "X.......\n........\n....X...\n........\n");
    put(f / "nofly.txt", "........\n........\n.......X\n........\n");
    put(f / "geo.yaml", "origin: [50, 8, 0]\nheading: 30\n");
    put(f / "defects.csv", "x_m,z_m,side,w_m,h_m\n1.0,0.5,starboard,1.0,0.5\n");
    put(f / "defects.json",
        R"({"defects": [{"x_m": 1.0, "z_m": 0.5, "side": "starboard", "w_m": 1.0, "h_m": 0.5}]})");
    put(f / "config.yaml", "name: tiny\nhull: " + (f / "hull.txt").string() +
                               "\ns1: 1\ns2: 3\nuavs: 1\nalgorithms: [lawnmower]\ninstances: 1\n"
                               "curve: {step: 10, end: 100}\n");
    put(f / "mesh.stl",
        "solid t\n facet normal 0 -1 0\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n"
        "   vertex 0 0 1\n  endloop\n endfacet\nendsolid t\n");
    const auto r = run_cli({"run", "--hull", (f / "hull.txt").string(), "-n", "1", "--s1", "1",
                            "--s2", "3", "--trace", (f / "trace.json").string()});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(fixtures_); }
  static inline std::string fixtures_;
};

TEST_F(InputOutputWalk, TheTableClassifiesEveryPathOptionOfEveryCommand) {
  for (const Command& c : commands()) {
    std::set<std::string> classified;
    for (const auto& [name, option] : c.options) classified.insert(name);
    EXPECT_EQ(path_options(c.words), classified) << c.words.front();
  }
}

// Arguments naming `value` for `name` (a positional is given bare).
void add(std::vector<std::string>& args, const std::string& name, const std::string& value) {
  if (name.starts_with("--")) args.push_back(name);
  args.push_back(value);
}

TEST_F(InputOutputWalk, NoOutputOptionCanOverwriteAnyInput) {
  int runs = 0;
  for (const Command& c : commands()) {
    for (const auto& [in_name, in] : c.options) {
      if (in.role != Role::kInput) continue;
      for (const auto& [out_name, out] : c.options) {
        if (out.role == Role::kInput) continue;
        for (const std::string variant : {"same path", "symbolic link", "hard link"}) {
          SCOPED_TRACE(c.words.front() + " " + in_name + " as " + out_name + ", " + variant);
          const fs::path dir = make_temp_dir("io-walk");
          const fs::path input = out.role == Role::kOutputDir && variant == "same path"
                                     ? dir / "d" / out.dir_entry
                                     : dir / ("in-" + in.fixture);
          // A defects file is read as JSON when its name ends in .json (preflight.json).
          const std::string fixture = in.fixture == "defects.csv" && input.extension() == ".json"
                                          ? "defects.json"
                                          : in.fixture;
          put(input, slurp(fs::path(fixtures_) / fixture));
          // Where the output goes: the input itself, or a link to it.
          const fs::path link =
              out.role == Role::kOutputDir ? dir / "d" / out.dir_entry : dir / "link.json";
          fs::create_directories(link.parent_path());
          if (variant == "symbolic link") fs::create_symlink(input, link);
          if (variant == "hard link") fs::create_hard_link(input, link);
          const fs::path target = variant == "same path" ? input : link;
          // `hull import --out NAME` writes NAME.json: only a name ending in .json is the file.
          if (c.words.back() == "import" && target.extension() != ".json") continue;

          std::vector<std::string> args = c.words;
          args.insert(args.end(), c.base.begin(), c.base.end());
          add(args, in_name, input.string());
          const fs::path out_path = out.role == Role::kOutputDir ? dir / "d" : target;
          add(args, out_name, out_path.string());
          // The other inputs a command needs: a trace for view and export, a hull, an export
          // directory for --geo, and --force so that an export directory holding the input is
          // refused for the input, not for not being empty; --report reports an export.
          if (c.options.contains("trace") && in_name != "trace") {
            add(args, "trace", (fs::path(fixtures_) / "trace.json").string());
          }
          if (in_name != "--hull" && c.options.contains("--hull")) {
            add(args, "--hull", (fs::path(fixtures_) / "hull.txt").string());
          }
          if (in_name == "--geo" && out.role != Role::kOutputDir) {
            add(args, c.options.contains("--export") ? "--export" : "--out", (dir / "e").string());
          }
          if (out.role == Role::kOutputDir && out.dir_entry == "uav0.csv")
            args.push_back("--force");
          if (out_name == "--report") add(args, "--export", (dir / "e").string());
          const auto before = snapshot(dir);
          const CliResult r = run_cli(args);
          ++runs;
          EXPECT_EQ(r.status, 2) << r.err;
          EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
          // Refused for the collision, not for some other problem of the arguments: a results
          // directory that already holds a file is refused as not empty before any input is read.
          EXPECT_TRUE(
              r.err.find("is the same file as") != std::string::npos ||
              (out.dir_entry == "runs.csv" && r.err.find("is not empty") != std::string::npos))
              << r.err;
          EXPECT_EQ(snapshot(dir), before) << "the command changed its directory";
          fs::remove_all(dir);
        }
      }
    }
  }
  EXPECT_GE(runs, 60);
  // The count docs/reliability.md quotes.
  std::cout << "input/output walk: " << runs << " runs\n";
}

}  // namespace
}  // namespace hullinspect::testing
