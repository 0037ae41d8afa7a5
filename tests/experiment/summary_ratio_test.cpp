// The report's tables show each planner's mean T_c and T_m beside the lower bound and their
// ratio to it (experiment/summary.hpp, summary_markdown).
#include <gtest/gtest.h>

#include "hullinspect/experiment/summary.hpp"

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
  return r;
}

TEST(SummaryRatio, EachMeanBesideTheBoundWithItsRatio) {
  const std::string md = summary_markdown(
      {row("lawnmower", 100, 300, 40, 150), row("sweep-inspect", 50, 225, 40, 150)});
  EXPECT_NE(md.find("(×: the mean over the lower bound's)"), std::string::npos) << md;
  EXPECT_NE(md.find("100.0 ± 0.0 (×2.50)"), std::string::npos) << md;
  EXPECT_NE(md.find("50.0 ± 0.0 (×1.25)"), std::string::npos) << md;
  EXPECT_NE(md.find("300.0 ± 0.0 (×2.00)"), std::string::npos) << md;
  EXPECT_NE(md.find("225.0 ± 0.0 (×1.50)"), std::string::npos) << md;
  EXPECT_NE(md.find("150.0"), std::string::npos) << md;
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
