// The pre-flight report's battery (docs/export.md "Pre-flight report"): with an endurance, a row
// per sortie of the planned mission whose margin is the endurance less the sortie's take-off to
// landing, as `plan --json` (the fields of `run --json`) reports the sorties.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "hullinspect/files/atomic_file.hpp"
#include "hullinspect/io/export.hpp"
#include "hullinspect/io/preflight_report.hpp"
#include "support/cli_runner.hpp"

namespace hullinspect::testing {
namespace {

namespace fs = std::filesystem;

constexpr double kEndurance = 400;

TEST(PreflightBattery, EverySortieHasTheMarginOfItsFlightTime) {
  const auto dir = make_temp_dir("preflight-battery");
  const auto r = run_cli({"plan",
                          "-a",
                          "sweep-inspect",
                          "-n",
                          "4",
                          "--launch",
                          "115,0",
                          "--endurance",
                          "400",
                          "--swap-time",
                          "60",
                          "--json",
                          "--trace",
                          dir + "/trace.json",
                          "--export",
                          dir + "/files",
                          "--format",
                          "csv",
                          "--report",
                          dir + "/report"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto result = nlohmann::json::parse(r.out);
  const auto report = nlohmann::json::parse(io::read_file(dir + "/report/preflight.json"));
  const auto& battery = report["battery"];
  ASSERT_EQ(battery["limited"], true);
  EXPECT_EQ(battery["endurance_s"], kEndurance);
  EXPECT_EQ(battery["reserve_s"], 40.0);  // 10 % of the endurance by default
  // One row per sortie of every UAV, in the mission's order, with its take-off and landing.
  std::size_t row = 0;
  double smallest = 1e9;
  int sorties = 0;
  for (std::size_t k = 0; k < result["launch"].size(); ++k) {
    const auto& flown = result["launch"][k]["sorties"];
    for (std::size_t n = 0; n < flown.size(); ++n, ++row) {
      ASSERT_LT(row, report["sorties"].size());
      const auto& s = report["sorties"][row];
      EXPECT_EQ(s["uav"], k);
      EXPECT_EQ(s["sortie"], n + 1);
      ASSERT_FALSE(flown[n]["landing"].is_null()) << k << " " << n;
      const double flight = flown[n]["landing"].get<double>() - flown[n]["takeoff"].get<double>();
      EXPECT_EQ(s["flight_time_s"], flight) << k << " " << n;
      EXPECT_EQ(s["battery_margin_s"], kEndurance - flight) << k << " " << n;
      EXPECT_GE(s["battery_margin_s"].get<double>(), 40.0) << k << " " << n;
      EXPECT_GT(s["waypoints"].get<int>(), 0) << k << " " << n;
      EXPECT_GT(s["distance_m"].get<double>(), 0) << k << " " << n;
      smallest = std::min(smallest, kEndurance - flight);
      ++sorties;
    }
  }
  EXPECT_EQ(row, report["sorties"].size());
  EXPECT_GT(sorties, 4);  // the battery made some UAV fly more than one sortie
  EXPECT_EQ(result["sorties"], sorties);
  EXPECT_EQ(battery["min_margin_s"], smallest);
  const auto warnings = report["warnings"].dump();
  EXPECT_EQ(warnings.find("below the reserve"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("sorties but its mission files hold them as one flight"),
            std::string::npos)
      << warnings;
  const auto md = io::read_file(dir + "/report/preflight.md");
  EXPECT_NE(md.find("battery margin (s)"), std::string::npos);
  EXPECT_NE(md.find(fmt::format("smallest margin: {:.1f} s", smallest)), std::string::npos) << md;

  // A sortie whose flight leaves less than the reserve is a warning naming it.
  const auto trace = nlohmann::json::parse(io::read_file(dir + "/trace.json"));
  const auto plan = io::export_plan(trace, "trace");
  io::PreflightBattery tight;
  tight.limited = true;
  tight.endurance_s = 100;
  tight.reserve_s = 30;
  tight.plan_end_s = 500;
  tight.sorties = {{{0, 60.0, 0}, {90, 180.0, 0}}};  // margins 40 s and 10 s
  const auto tight_report = io::preflight_report(trace, plan, {}, {}, std::nullopt, tight);
  EXPECT_EQ(tight_report["sorties"][0]["battery_margin_s"], 40.0);
  EXPECT_EQ(tight_report["sorties"][1]["battery_margin_s"], 10.0);
  EXPECT_EQ(tight_report["battery"]["min_margin_uav"], 0);
  EXPECT_EQ(tight_report["battery"]["min_margin_sortie"], 2);
  const auto tight_warnings = tight_report["warnings"].dump();
  EXPECT_NE(tight_warnings.find("UAV 0 sortie 2: battery margin 10.0 s is below the reserve of "
                                "30.0 s"),
            std::string::npos)
      << tight_warnings;
  EXPECT_EQ(tight_warnings.find("UAV 0 sortie 1: battery"), std::string::npos) << tight_warnings;
  fs::remove_all(dir);
}

TEST(PreflightBattery, UnlimitedFlightSaysSo) {
  const auto dir = make_temp_dir("preflight-unlimited");
  const auto r = run_cli({"plan", "-n", "2", "--export", dir + "/files", "--format", "csv",
                          "--report", dir + "/report"});
  ASSERT_EQ(r.status, 0) << r.err;
  const auto report = nlohmann::json::parse(io::read_file(dir + "/report/preflight.json"));
  EXPECT_EQ(report["battery"]["limited"], false);
  EXPECT_NE(report["battery"]["note"].get<std::string>().find("unlimited flight"),
            std::string::npos);
  for (const auto& s : report["sorties"]) EXPECT_TRUE(s["battery_margin_s"].is_null());
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hullinspect::testing
