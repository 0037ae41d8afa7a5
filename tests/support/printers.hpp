#pragma once
// GoogleTest printers for project types, so failures read "(3, 11)" rather than raw bytes.

#include <ostream>

#include "hullinspect/grid/cell.hpp"

namespace hullinspect::grid {
inline void PrintTo(const Cell& c, std::ostream* os) { *os << "(" << c.x << ", " << c.y << ")"; }
}  // namespace hullinspect::grid
