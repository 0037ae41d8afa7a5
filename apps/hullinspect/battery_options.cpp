#include "battery_options.hpp"

namespace hullinspect::cli {

void add_battery_options(CLI::App& cmd, BatteryArgs& a) {
  cmd.add_option("--endurance", a.endurance,
                 "Seconds of flight per battery (default: unlimited, the paper's model); needs "
                 "--launch: a UAV is sent home to swap its battery before it runs low, and one "
                 "airborne with an empty battery crashes (docs/model.md)")
      ->type_name("S");
  cmd.add_option("--reserve", a.reserve,
                 "With --endurance: seconds of flight a UAV keeps for landing (default: 10 % of "
                 "the endurance)")
      ->type_name("S");
  cmd.add_option("--swap-time", a.swap_time,
                 "With --endurance: seconds on the ground at a launch site to swap a battery")
      ->type_name("S")
      ->capture_default_str();
}

void apply_battery_args(const BatteryArgs& a, world::MissionParams& p) {
  p.endurance_s = a.endurance;
  p.reserve_s = a.reserve;
  p.swap_time_s = a.swap_time;
}

}  // namespace hullinspect::cli
