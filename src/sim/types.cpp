#include "hullinspect/sim/types.hpp"

namespace hullinspect::sim {

std::string_view to_string(Action a) {
  switch (a) {
    case Action::kHover:
      return "hover";
    case Action::kNorth:
      return "north";
    case Action::kSouth:
      return "south";
    case Action::kEast:
      return "east";
    case Action::kWest:
      return "west";
    case Action::kChangePlane:
      return "change-plane";
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
    case Action::kNorth:
      return {c.x, c.y + 1};
    case Action::kSouth:
      return {c.x, c.y - 1};
    case Action::kEast:
      return {c.x + 1, c.y};
    case Action::kWest:
      return {c.x - 1, c.y};
    default:
      return c;
  }
}

grid::Cell moved(grid::Cell c, Action a, int width, int height, const grid::EdgeSteps& steps) {
  int d = -1;
  switch (a) {
    case Action::kEast:
      d = 0;
      break;
    case Action::kWest:
      d = 1;
      break;
    case Action::kNorth:
      d = 2;
      break;
    case Action::kSouth:
      d = 3;
      break;
    default:
      return c;
  }
  const grid::Cell n = grid::neighbour(c, d, width, height, steps);
  return n == grid::kNoCell ? moved(c, a) : n;
}

Action move_to_neighbour(grid::Cell from, grid::Cell next) {
  // Two positions of a row more than a column apart are neighbours only across the seam, where
  // column 0's west is column W − 1.
  if (next.y == from.y && (next.x - from.x > 1 || from.x - next.x > 1)) {
    return next.x > from.x ? Action::kWest : Action::kEast;
  }
  return step_towards(from, next);
}

}  // namespace hullinspect::sim
