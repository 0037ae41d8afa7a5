// tools/plot_mission.py on a real trace: a PNG and a PDF, or one line and exit 2 for a bad trace.

#include <gtest/gtest.h>
#include "source_dir.hpp"
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "support/cli_runner.hpp"

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int shell(const std::string& command) {
  const int raw = std::system(command.c_str());
  return WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
}

class PlotMission : public ::testing::Test {
 protected:
  void SetUp() override {
    const char* source = std::getenv("HULLINSPECT_SOURCE_DIR");
    cli_ = hullinspect::testing::cli_path();
    script_ =
        fs::path(source != nullptr ? source : HULLINSPECT_SOURCE_DIR) / "tools" / "plot_mission.py";
    dir_ = hullinspect::testing::make_temp_dir("plot-mission");
  }
  void TearDown() override { fs::remove_all(dir_); }

  int plot(const std::string& args) const {
    return shell("/usr/bin/python3 '" + script_.string() + "' " + args + " >'" +
                 (dir_ / "out.txt").string() + "' 2>'" + (dir_ / "err.txt").string() + "'");
  }

  std::string cli_;
  fs::path script_;
  fs::path dir_;
};

TEST_F(PlotMission, WritesPngAndPdfOfARealMission) {
  const auto trace = dir_ / "m.json";
  ASSERT_EQ(
      shell("'" + cli_ + "' run -n 3 --s2 9 --seed 5 --trace '" + trace.string() + "' >/dev/null"),
      0);
  ASSERT_EQ(plot("'" + trace.string() + "' --time 60"), 0) << slurp(dir_ / "err.txt");
  // Default outputs: the trace's name with .png and .pdf.
  EXPECT_EQ(slurp(dir_ / "m.png").substr(0, 8), "\x89PNG\r\n\x1a\n");
  EXPECT_EQ(slurp(dir_ / "m.pdf").substr(0, 5), "%PDF-");
  EXPECT_EQ(slurp(dir_ / "out.txt"),
            "wrote " + (dir_ / "m.png").string() + "\nwrote " + (dir_ / "m.pdf").string() + "\n");
}

TEST_F(PlotMission, BadTraceOrTimeIsOneLineAndExit2) {
  const auto bad = dir_ / "bad.json";
  std::ofstream(bad) << "{\"format\": \"something\"}";
  EXPECT_EQ(plot("'" + bad.string() + "' -o '" + (dir_ / "x.png").string() + "'"), 2);
  EXPECT_EQ(slurp(dir_ / "err.txt"), "plot_mission.py: " + bad.string() +
                                         ": format: expected \"hullinspect-trace\" (not a "
                                         "hullinspect trace?)\n");
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));

  const auto trace = dir_ / "m.json";
  ASSERT_EQ(shell("'" + cli_ + "' run -n 8 --trace '" + trace.string() + "' >/dev/null"), 0);
  EXPECT_EQ(plot("'" + trace.string() + "' --time 100000"), 2);
  EXPECT_EQ(slurp(dir_ / "err.txt").rfind("plot_mission.py: --time: 100000 is outside [0, ", 0),
            0u);
}

}  // namespace
