// The report's sorties (experiment/summary.hpp): where runs flew sorties from launch sites, each
// cell's per-UAV sorties and flight time, the smallest battery margin and the crashes, in the
// tables and in summary.csv; nothing of them for runs without launch sites.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "hullinspect/experiment/csv.hpp"
#include "hullinspect/experiment/summary.hpp"

namespace hullinspect::experiment {
namespace {

// runs.csv rows (perfect, s2 = 7): algorithm, uavs, then sorties, flight_s, battery_crashes,
// min_battery_s.
CsvTable runs(const std::vector<std::string>& rows) {
  std::string text =
      "scenario,sweep,sweep_value,algorithm,s2,uavs,complete,T_c,T_m,sorties,flight_s,"
      "battery_crashes,min_battery_s\n";
  for (const auto& r : rows) text += "perfect,,," + r + "\n";
  return parse_csv(text, "runs.csv");
}

TEST(SummarySorties, PerUavMeansTheSmallestMarginAndTheCrashes) {
  // Two missions of 4 UAVs: 8 and 12 sorties, 2000 and 2400 s flown, margins 35 and 20.5 s.
  const auto rows = summarize_runs(
      runs({"lawnmower,7,4,1,100,200,8,2000,0,35", "lawnmower,7,4,1,110,210,12,2400,1,20.5"}),
      "runs.csv");
  ASSERT_EQ(rows.size(), 1U);
  const auto& s = rows[0].sorties;
  EXPECT_EQ(s.runs, 2);
  EXPECT_DOUBLE_EQ(s.per_uav, 2.5);
  EXPECT_DOUBLE_EQ(s.flight_s_per_uav, 550);
  ASSERT_TRUE(s.min_battery_s.has_value());
  EXPECT_DOUBLE_EQ(*s.min_battery_s, 20.5);
  EXPECT_EQ(s.battery_crashes, 1);

  const std::string md = summary_markdown(rows);
  EXPECT_NE(md.find("### perfect — sorties"), std::string::npos) << md;
  EXPECT_NE(md.find("|   7 |   4 | lawnmower |    2 |            2.50 |              550.0 |     "
                    "                   20.5 |               1 |"),
            std::string::npos)
      << md;
  const std::string csv = summary_csv(rows);
  EXPECT_NE(
      csv.find(",sortie_runs,sorties_per_uav,flight_s_per_uav,min_battery_s,battery_crashes\n"),
      std::string::npos)
      << csv;
  EXPECT_NE(csv.find(",2,2.500,550.000,20.500,1\n"), std::string::npos) << csv;
}

// Launch sites with unlimited flight: sorties but no battery margin.
TEST(SummarySorties, UnlimitedFlightHasNoMargin) {
  const auto rows = summarize_runs(runs({"sweep-inspect,7,2,1,100,200,2,380,0,"}), "runs.csv");
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_FALSE(rows[0].sorties.min_battery_s.has_value());
  EXPECT_NE(summary_markdown(rows).find("unlimited"), std::string::npos) << summary_markdown(rows);
}

// The paper's model (no launch site): no sortie counted, no sortie table, empty csv fields; and a
// runs.csv from before batteries (no sortie columns) reads as before.
TEST(SummarySorties, NoneWithoutLaunchSites) {
  const auto rows = summarize_runs(runs({"lawnmower,7,4,1,100,200,0,800,0,"}), "runs.csv");
  ASSERT_EQ(rows.size(), 1U);
  EXPECT_EQ(rows[0].sorties.runs, 0);
  EXPECT_EQ(summary_markdown(rows).find("sorties"), std::string::npos) << summary_markdown(rows);
  EXPECT_NE(summary_csv(rows).find(",0,,,,\n"), std::string::npos) << summary_csv(rows);

  const auto old =
      summarize_runs(parse_csv("scenario,sweep,sweep_value,algorithm,s2,uavs,complete,T_c,T_m\n"
                               "perfect,,,lawnmower,7,4,1,100,200\n",
                               "runs.csv"),
                     "runs.csv");
  ASSERT_EQ(old.size(), 1U);
  EXPECT_EQ(old[0].sorties.runs, 0);
}

}  // namespace
}  // namespace hullinspect::experiment
