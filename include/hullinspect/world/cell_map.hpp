#pragma once
// Cell maps in the hull-mask formats (text or PGM) read without the hull checks: any shape,
// possibly empty — for maps over a hull such as the user's corrosion maps.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "hullinspect/grid/grid.hpp"

namespace hullinspect::world {

/// 1 for marked cells ('X' or '#' in text, grey > maxval/2 in PGM), 0 otherwise; rows as in a
/// hull mask (the first row read is the top, y = b − 1). Throws InputError naming `source`.
grid::Grid<std::uint8_t> parse_text_cells(std::string_view text, const std::string& source);
grid::Grid<std::uint8_t> parse_pgm_cells(std::string_view bytes, const std::string& source);
/// Reads a text or PGM cell map file (format by content, like load_hull).
grid::Grid<std::uint8_t> load_cell_map(const std::filesystem::path& path);

}  // namespace hullinspect::world
