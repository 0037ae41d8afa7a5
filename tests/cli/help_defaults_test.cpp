// The defaults that `--help` shows for the mesh and export options are the ones the commands use:
// a hull imported without options records them, an export without --format is written in it.

#include <gtest/gtest.h>
#include "source_dir.hpp"
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/mesh_fixtures.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

// The default shown for `option` in a CLI11 help text ("  --side TEXT=starboard  Side ..."):
// the text after '=' in the word after the option's name; "" when none is shown.
std::string shown_default(const std::string& help, const std::string& option) {
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string name, type;
    words >> name;
    if (name != option && name.find("," + option) == std::string::npos) continue;
    words >> type;
    const auto eq = type.find('=');
    return eq == std::string::npos ? "" : type.substr(eq + 1);
  }
  ADD_FAILURE() << option << " is not in the help:\n" << help;
  return "";
}

// The hull JSON's record of an option as the help writes it.
std::string recorded(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  std::ostringstream out;
  out << value.get<double>();
  return out.str();
}

TEST(HelpDefaults, MeshOptionsShowWhatAnImportWithoutOptionsUses) {
  const auto dir = make_temp_dir("help-defaults-mesh");
  const std::string stl = wigley_stl(WigleyHull{}).string();
  const auto r = run_cli({"hull", "import", stl, "--out", dir + "/plain"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto hull = nlohmann::json::parse(std::ifstream(dir + "/plain.json"));
  // Every command that takes a mesh shows the same defaults.
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"hull", "import"}, {"run"}, {"partition"}, {"plan"}}) {
    auto args = command;
    args.push_back("--help");
    const auto help = run_cli(args);
    ASSERT_EQ(help.status, 0) << help.err;
    SCOPED_TRACE(command.back());
    for (const char* field : {"side", "scale", "axes", "min_coverage", "cell_size"}) {
      std::string option = std::string("--") + field;
      std::replace(option.begin(), option.end(), '_', '-');
      EXPECT_EQ(shown_default(help.out, option), recorded(hull[field])) << option;
    }
    // No waterline by default: none shown as a value, the help says so in words.
    EXPECT_TRUE(hull["waterline"].is_null());
    EXPECT_EQ(shown_default(help.out, "--waterline"), "");
    EXPECT_NE(help.out.find("(default: none, a hull in dry dock)"), std::string::npos);
  }
  fs::remove_all(dir);
}

// docs/hulls.md's table of options shows the same defaults as --help.
TEST(HelpDefaults, HullsDocTableShowsTheHelpDefaults) {
  std::ifstream doc(fs::path(HULLINSPECT_SOURCE_DIR) / "docs" / "hulls.md");
  ASSERT_TRUE(doc) << "docs/hulls.md";
  const auto help = run_cli({"hull", "import", "--help"});
  ASSERT_EQ(help.status, 0) << help.err;
  int rows = 0;
  for (std::string line; std::getline(doc, line);) {
    // | `--side port\|starboard` | starboard | meaning |
    if (line.rfind("| `--", 0) != 0) continue;
    const auto name_end = line.find_first_of(" `", 5);
    const std::string option = line.substr(5, name_end - 5);
    if (option == "out" || option == "keep-largest") continue;
    const auto cell = line.find("| ", line.find("` |")) + 2;
    std::string shown = line.substr(cell, line.find(" |", cell) - cell);
    shown.erase(std::remove(shown.begin(), shown.end(), '`'), shown.end());
    const std::string from_help = shown_default(help.out, "--" + option);
    EXPECT_EQ(shown, from_help.empty() ? "none" : from_help) << "--" << option;
    ++rows;
  }
  EXPECT_EQ(rows, 6);
}

TEST(HelpDefaults, ExportFormatShownIsTheOneWrittenWithoutFormat) {
  const auto dir = make_temp_dir("help-defaults-export");
  const std::string trace = dir + "/mission.json";
  const auto run = run_cli({"run", "--uavs", "2", "--seed", "1", "--trace", trace});
  ASSERT_EQ(run.status, 0) << run.err;
  const auto r = run_cli({"export", trace, "--out", dir + "/plans"});
  ASSERT_EQ(r.status, 0) << r.err;
  std::set<std::string> extensions;
  for (const auto& entry : fs::directory_iterator(dir + "/plans")) {
    extensions.insert(entry.path().extension().string());
  }
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"export"}, {"run"}, {"plan"}}) {
    auto args = command;
    args.push_back("--help");
    const auto help = run_cli(args);
    ASSERT_EQ(help.status, 0) << help.err;
    EXPECT_EQ(extensions, std::set<std::string>{"." + shown_default(help.out, "--format")})
        << command.front();
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
