// The report's tables show each planner's mean T_c and T_m beside the lower bound and their
// ratio to it (experiment/summary.hpp, summary_markdown).
#include <gtest/gtest.h>

#include "hullinspect/experiment/summary.hpp"

#include <string>
#include <vector>

#include "hullinspect/experiment/csv.hpp"

namespace hullinspect::experiment {
namespace {

SummaryRow row(const std::string& algorithm, double t_c, double t_m, double bound_c,
               double bound_m) {
  SummaryRow r;
  r.scenario = "perfect";
  r.algorithm = algorithm;
  r.s2 = 7;
  r.uavs = 4;
  r.runs = 2;
  r.t_c = {2, t_c, 0};
  r.t_m = {2, t_m, 0};
  r.bound_t_c = {2, bound_c, 0};
  r.bound_t_m = {2, bound_m, 0};
  r.t_c_bound = bound_c;
  r.t_m_bound = bound_m;
  return r;
}

// runs.csv rows of one cell (perfect, s2 = 7, n = 4): complete, T_c, T_m, bound_T_c, bound_T_m.
CsvTable runs(const std::string& algorithm, const std::vector<std::string>& rows) {
  std::string text =
      "scenario,sweep,sweep_value,algorithm,s2,uavs,complete,T_c,T_m,bound_T_c,"
      "bound_T_m\n";
  for (const auto& r : rows) text += "perfect,,," + algorithm + ",7,4," + r + "\n";
  return parse_csv(text, "runs.csv");
}

TEST(SummaryRatio, EachMeanBesideTheBoundWithItsRatio) {
  const std::string md = summary_markdown(
      {row("lawnmower", 100, 300, 40, 150), row("sweep-inspect", 50, 225, 40, 150)});
  EXPECT_NE(md.find("(×: the mean over the mean lower bound of the same missions)"),
            std::string::npos)
      << md;
  EXPECT_NE(md.find("100.0 ± 0.0 (×2.50)"), std::string::npos) << md;
  EXPECT_NE(md.find("50.0 ± 0.0 (×1.25)"), std::string::npos) << md;
  EXPECT_NE(md.find("300.0 ± 0.0 (×2.00)"), std::string::npos) << md;
  EXPECT_NE(md.find("225.0 ± 0.0 (×1.50)"), std::string::npos) << md;
  EXPECT_NE(md.find("150.0"), std::string::npos) << md;
}

// A mission that did not complete has no T_m: the ratio pairs the mean T_m of the missions that
// reached it with the mean bound of those missions, not of every mission of the cell.
TEST(SummaryRatio, PairsEachTimeWithTheBoundOfTheSameMissions) {
  const auto rows = summarize_runs(
      runs("lawnmower", {"1,100,300,40,100", "0,90,,60,200", "1,120,400,50,100"}), "runs.csv");
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_DOUBLE_EQ(rows[0].t_m.mean, 350);
  EXPECT_DOUBLE_EQ(rows[0].t_m_bound, 100);              // the two complete missions' bounds
  EXPECT_DOUBLE_EQ(rows[0].t_c_bound, 50);               // every mission reached T_c
  EXPECT_NEAR(rows[0].bound_t_m.mean, 400.0 / 3, 1e-9);  // the column: every mission's
  const std::string md = summary_markdown(rows);
  EXPECT_NE(md.find("350.0 ± 70.7 (×3.50) [1 incomplete]"), std::string::npos) << md;
  EXPECT_NE(md.find("(×2.07)"), std::string::npos) << md;  // T_c 103.3 over 50
}

// A merged runs.csv may hold missions without a bound: the ratio is over the missions with both.
TEST(SummaryRatio, LeavesOutTheTimesOfMissionsWithoutABound) {
  const auto rows =
      summarize_runs(runs("lawnmower", {"1,100,300,40,100", "1,200,500,,"}), "runs.csv");
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_DOUBLE_EQ(rows[0].t_m.mean, 400);
  const std::string md = summary_markdown(rows);
  EXPECT_NE(md.find("400.0 ± 141.4 (×3.00)"), std::string::npos) << md;  // 300 over 100
  EXPECT_NE(md.find("150.0 ± 70.7 (×2.50)"), std::string::npos) << md;   // 100 over 40
}

TEST(SummaryRatio, NoRatioWhenNoMissionHasBothATimeAndABound) {
  const auto rows = summarize_runs(runs("lawnmower", {"0,,,40,100", "1,80,200,,"}), "runs.csv");
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_EQ(rows[0].t_m_bound, 0);
  const std::string md = summary_markdown(rows);
  EXPECT_NE(md.find("| 80.0 ± 0.0 [1 incomplete] |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 200.0 ± 0.0 [1 incomplete] |"), std::string::npos) << md;
}

TEST(SummaryRatio, NoRatioWithoutABound) {
  SummaryRow r = row("lawnmower", 100, 300, 0, 0);
  r.bound_t_c = {};
  r.bound_t_m = {};
  const std::string md = summary_markdown({r});
  EXPECT_EQ(md.find("×"), std::string::npos) << md;
  EXPECT_EQ(md.find("lower bound"), std::string::npos) << md;
}

}  // namespace
}  // namespace hullinspect::experiment
