#pragma once
// The finite-state machine of Part-TSP (paper Fig. 3, model.md §5.3) that decides when a UAV changes
// plane. It is evaluated every step for a UAV that is on a plane, before it acts.

#include <cstdint>
#include <string_view>

namespace hullinspect::planners::part_tsp {

struct FsmInput {
  int z = 2;        ///< current plane
  int h = 0;        ///< cells of R_k with M^k = 2
  int unknown = 0;  ///< cells of R_k with M^k = 0
  int t_d = 0;      ///< steps since the UAV's last detection (since mission start if none)
  int t_i = 0;      ///< steps since its last inspection or last arrival at z = 1, the later one
};

enum class FsmDecision : std::uint8_t {
  kStay,         ///< keep working on this plane
  kChangePlane,  ///< descend (z = 2) or ascend (z = 1) now
  kDone,         ///< nothing left in R_k: hover
};

/// At z = 2: descend if h > 0 and (t_d ≥ r1 or no 0 is left). At z = 1: ascend if h = 0, t_i ≥ r2
/// and some 0 is left. Whatever the plane: done when h = 0 and no 0 is left.
FsmDecision evaluate_fsm(const FsmInput& in, int r1, int r2);

/// The value a plan on plane z targets: 0 at z = 2 (coverage); at z = 1, 2 (inspection) while
/// h > 0, else 0 (a UAV that r2 keeps down covers from z = 1).
std::int8_t target_value(int z, int h);

/// Trace names of the FSM states.
inline constexpr std::string_view kModeCoverZ2 = "cover-z2";
inline constexpr std::string_view kModeInspectZ1 = "inspect-z1";
inline constexpr std::string_view kModeCoverZ1 = "cover-z1";
inline constexpr std::string_view kModeDescending = "descending";
inline constexpr std::string_view kModeAscending = "ascending";
inline constexpr std::string_view kModeDone = "done";
inline constexpr std::string_view kModeFailed = "failed";

}  // namespace hullinspect::planners::part_tsp
