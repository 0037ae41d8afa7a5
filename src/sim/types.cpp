#include "hullinspect/sim/types.hpp"

namespace hullinspect::sim {

std::string_view to_string(Action a) {
  switch (a) {
    case Action::kHover: return "hover";
    case Action::kNorth: return "north";
    case Action::kSouth: return "south";
    case Action::kEast: return "east";
    case Action::kWest: return "west";
    case Action::kChangePlane: return "change-plane";
  }
  return "?";
}

Action step_towards(grid::Cell from, grid::Cell to) {
  if (to.x > from.x) return Action::kEast;
  if (to.x < from.x) return Action::kWest;
  if (to.y > from.y) return Action::kNorth;
  if (to.y < from.y) return Action::kSouth;
  return Action::kHover;
}

grid::Cell moved(grid::Cell c, Action a) {
  switch (a) {
    case Action::kNorth: return {c.x, c.y + 1};
    case Action::kSouth: return {c.x, c.y - 1};
    case Action::kEast: return {c.x + 1, c.y};
    case Action::kWest: return {c.x - 1, c.y};
    default: return c;
  }
}

}  // namespace hullinspect::sim
