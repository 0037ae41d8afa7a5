// The bad-input table: every row of tests/cli/bad_inputs.jsonl runs one hullinspect command on a
// fresh directory of valid fixture files (plus the row's own files) and must exit with the row's
// status (2 unless given) and exactly the row's one-line message on stderr, print nothing on
// stdout, and leave the directory exactly as it was: no file created (not even a temporary), none
// changed, none removed. In the table, "@" stands for the row's directory followed by '/'.
//
// A row may also create symbolic links ("links": {"name": "target"}) and FIFOs ("fifos": [names]).
//
// Fixtures in every row's directory: hull.txt (8 × 4 hull), hull.pgm (P2), tsp.json, config.yaml
// (a 2-run experiment on hull.txt), trace.json (a mission on hull.txt), results/ (the finished
// experiment of config.yaml).
//
// HULLINSPECT_UPDATE_BAD_INPUTS=1 rewrites the table's messages and statuses with what the CLI
// prints now (then review the diff: every change must be intended).

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <nlohmann/json.hpp>
#include "source_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/dir_snapshot.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

struct Row {
  std::string id;
  std::vector<std::string> args;
  std::map<std::string, std::string> files;  // extra files: name -> content
  std::map<std::string, std::string> links;  // symbolic links: name -> target
  std::vector<std::string> fifos;            // named pipes (nobody writes to them)
  std::string message;
  int status = 2;
};

fs::path table_path() {
  const char* src = std::getenv("HULLINSPECT_SOURCE_DIR");
  return fs::path(src != nullptr ? src : HULLINSPECT_SOURCE_DIR) / "tests/cli/bad_inputs.jsonl";
}

std::vector<Row> load_rows() {
  std::vector<Row> rows;
  std::ifstream in(table_path());
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto j = nlohmann::json::parse(line);
    Row r;
    r.id = j.at("id").get<std::string>();
    r.args = j.at("args").get<std::vector<std::string>>();
    if (j.contains("files")) r.files = j.at("files").get<std::map<std::string, std::string>>();
    if (j.contains("links")) r.links = j.at("links").get<std::map<std::string, std::string>>();
    if (j.contains("fifos")) r.fifos = j.at("fifos").get<std::vector<std::string>>();
    r.message = j.value("message", "");
    r.status = j.value("status", 2);
    rows.push_back(std::move(r));
  }
  return rows;
}

std::string replace_all(std::string s, const std::string& from, const std::string& to) {
  for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + to.size())) {
    s.replace(at, from.size(), to);
  }
  return s;
}

class BadInputTable : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    fixtures_ = make_temp_dir("bad-input-fixtures");
    const fs::path f = fixtures_;
    std::ofstream(f / "hull.txt") << "XXXXXXXX\nXXXXXXXX\nXXXXXXXX\nXXXXXXXX\n";
    std::ofstream(f / "hull.pgm") << "P2\n4 2\n255\n255 255 255 255\n255 255 255 0\n";
    std::ofstream(f / "tsp.json")
        << R"({"start": [0, 0], "segments": [[[1, 1], [1, 4]], [[3, 0], [5, 0]]]})";
    std::ofstream(f / "config.yaml") << "name: tiny\nhull: hull.txt\ns2: 7\nuavs: 2\n"
                                        "algorithms: [lawnmower]\ninstances: 2\ntime_limit: 2000\n"
                                        "curve: {step: 10, end: 100}\n";
    auto r = run_cli({"run", "--hull", (f / "hull.txt").string(), "-n", "2", "--trace",
                      (f / "trace.json").string()});
    ASSERT_EQ(r.status, 0) << r.err;
    r = run_cli({"experiment", "--config", (f / "config.yaml").string(), "--out",
                 (f / "results").string(), "--jobs", "1"});
    ASSERT_EQ(r.status, 0) << r.err;
  }
  static void TearDownTestSuite() { fs::remove_all(fixtures_); }
  static inline std::string fixtures_;
};

TEST_F(BadInputTable, EveryRowIsOneLineExitTwoAndTouchesNothing) {
  auto rows = load_rows();
  ASSERT_GE(rows.size(), 200u) << "the table must hold at least 200 rows";
  const bool update = std::getenv("HULLINSPECT_UPDATE_BAD_INPUTS") != nullptr;
  std::map<std::string, int> ids;
  for (auto& row : rows) {
    SCOPED_TRACE(row.id);
    EXPECT_EQ(ids[row.id]++, 0) << "duplicate row id";
    const fs::path dir = make_temp_dir("bad-input-row");
    fs::copy(fixtures_, dir, fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    for (const auto& [name, content] : row.files) {
      fs::create_directories((dir / name).parent_path());
      std::ofstream(dir / name, std::ios::binary) << content;
    }
    for (const auto& [name, target] : row.links) {
      fs::create_directories((dir / name).parent_path());
      fs::create_symlink(target, dir / name);
    }
    for (const auto& name : row.fifos) ASSERT_EQ(::mkfifo((dir / name).c_str(), 0666), 0) << name;
    const std::string at = dir.string() + "/";
    std::vector<std::string> args;
    for (const auto& a : row.args) args.push_back(replace_all(a, "@", at));
    const auto before = snapshot(dir);
    const auto r = run_cli(args);
    const std::string err = replace_all(r.err, at, "@");
    if (update) {
      row.message = err.empty() || err.back() != '\n' ? err : err.substr(0, err.size() - 1);
      row.status = r.status;
    } else {
      EXPECT_EQ(r.status, row.status);
      EXPECT_EQ(err, row.message + "\n");
      EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one line";
      EXPECT_EQ(r.out, "");
      EXPECT_EQ(snapshot(dir), before) << "the command changed its directory";
    }
    fs::remove_all(dir);
  }
  if (update) {
    std::ofstream out(table_path());
    for (const auto& row : rows) {
      nlohmann::ordered_json j;
      j["id"] = row.id;
      j["args"] = row.args;
      if (!row.files.empty()) j["files"] = row.files;
      if (!row.links.empty()) j["links"] = row.links;
      if (!row.fifos.empty()) j["fifos"] = row.fifos;
      j["message"] = row.message;
      if (row.status != 2) j["status"] = row.status;
      out << j.dump() << "\n";
    }
  }
}

}  // namespace
}  // namespace hullinspect::testing
