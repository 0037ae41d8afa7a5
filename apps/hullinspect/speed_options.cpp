#include "speed_options.hpp"

namespace hullinspect::cli {

void add_speed_options(CLI::App& cmd, SpeedArgs& a) {
  cmd.add_option("--speed", a.speed,
                 "Horizontal speed in m/s: a move to a neighbouring cell takes cell / speed "
                 "seconds, the length of one step (default: one cell per second)")
      ->type_name("M/S");
  cmd.add_option("--climb-speed", a.climb_speed,
                 "Climb speed in m/s for plane changes and the take-off, rounded up to whole steps "
                 "(default: one cell per second, u_z steps at the default speed)")
      ->type_name("M/S");
}

void apply_speed_options(const SpeedArgs& a, world::MissionParams& p) {
  p.speed_m_s = a.speed;
  p.climb_speed_m_s = a.climb_speed;
}

}  // namespace hullinspect::cli
