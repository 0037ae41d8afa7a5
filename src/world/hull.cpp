#include "hullinspect/world/hull.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <sstream>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/files/bounded_read.hpp"
#include "hullinspect/grid/distance.hpp"
#include "hullinspect/world/cell_map.hpp"
#include "hullinspect/world/mesh_hull.hpp"

namespace hullinspect::world {

namespace detail {
extern const std::string_view kDefaultHullText;
}

namespace {
// A hull file larger than this is refused before it is read whole (a 4096 × 4096 P5 image with
// 16-bit pixels is 32 MiB; a text mask 16 MiB plus comments).
constexpr std::size_t kMaxHullFileBytes = std::size_t{64} << 20;
}  // namespace

HullMask::HullMask(grid::Grid<std::uint8_t> is_hull, std::string source)
    : mask_(std::move(is_hull)), source_(std::move(source)) {
  if (mask_.width() < 1 || mask_.height() < 1 || mask_.width() > kMaxGridSide ||
      mask_.height() > kMaxGridSide) {
    throw InputError(source_, 0,
                     fmt::format("grid is {} × {}; each side must be within 1..{}", mask_.width(),
                                 mask_.height(), kMaxGridSide));
  }
  for (int i = 0; i < mask_.size(); ++i) {
    if (mask_[i]) {
      mask_[i] = 1;
      cells_.push_back(i);
    }
  }
  cell_count_ = static_cast<int>(cells_.size());
  if (cell_count_ == 0) throw InputError(source_, 0, "the hull is empty (no hull cells)");
  grid::Grid<int> labels;
  grid::BfsScratch scratch;
  const int components = grid::label_components(mask_, labels, scratch);
  if (components > 1) {
    std::vector<int> sizes(static_cast<std::size_t>(components), 0);
    std::vector<grid::Cell> first(static_cast<std::size_t>(components), {-1, -1});
    for (int i : cells_) {
      auto k = static_cast<std::size_t>(labels[i]);
      if (sizes[k]++ == 0) first[k] = mask_.cell(i);
    }
    std::string parts;
    for (std::size_t k = 0; k < sizes.size() && k < 5; ++k) {
      parts +=
          fmt::format("{}{} cells from ({}, {})", k ? "; " : "", sizes[k], first[k].x, first[k].y);
    }
    if (sizes.size() > 5) parts += "; …";
    throw InputError(
        source_, 0,
        fmt::format("the hull is not 4-connected: {} components ({})", components, parts));
  }
}

grid::Cell HullMask::snap(grid::Cell c) const {
  // A hull cell is its own unique nearest hull cell (distance 0). Every mission snaps its start
  // cells several times (validation, simulator, bound, partition), and the scan below is O(hull).
  if (mask_.contains(c) && mask_(c.x, c.y) != 0) return c;
  grid::Cell best{-1, -1};
  int best_d = grid::kUnreachable;
  for (int i : cells_) {  // (y, x) order, so the first strict minimum wins ties
    const grid::Cell h = mask_.cell(i);
    const int d = grid::manhattan(h, c);
    if (d < best_d) {
      best_d = d;
      best = h;
    }
  }
  return best;
}

grid::Grid<std::uint8_t> parse_text_cells(std::string_view text, const std::string& source) {
  std::vector<std::string> rows;
  std::vector<int> row_lines;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos <= text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string_view::npos) end = text.size();
    std::string line(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty() || line[0] == ';') {
      if (end == text.size()) break;
      continue;
    }
    for (std::size_t col = 0; col < line.size(); ++col) {
      const char ch = line[col];
      if (ch != 'X' && ch != '#' && ch != '.') {
        throw InputError(source, line_no,
                         fmt::format("unexpected character '{}' in column {}; a text mask uses 'X' "
                                     "or '#' (hull) and '.' (not hull)",
                                     escape_for_message(std::string_view(&line[col], 1)), col + 1));
      }
    }
    if (!rows.empty() && line.size() != rows.front().size()) {
      throw InputError(source, line_no,
                       fmt::format("row has {} cells but the first row has {}", line.size(),
                                   rows.front().size()));
    }
    if (line.size() > static_cast<std::size_t>(kMaxGridSide)) {
      throw InputError(
          source, line_no,
          fmt::format("row has {} cells; at most {} are accepted", line.size(), kMaxGridSide));
    }
    rows.push_back(std::move(line));
    row_lines.push_back(line_no);
    if (rows.size() > static_cast<std::size_t>(kMaxGridSide)) {
      throw InputError(source, line_no, fmt::format("more than {} rows", kMaxGridSide));
    }
    if (end == text.size()) break;
  }
  if (rows.empty()) throw InputError(source, 0, "no mask rows (the file is empty)");
  const int height = static_cast<int>(rows.size());
  const int width = static_cast<int>(rows.front().size());
  grid::Grid<std::uint8_t> mask(width, height, 0);
  for (int r = 0; r < height; ++r) {
    const int y = height - 1 - r;  // first text row is the top of the hull
    for (int x = 0; x < width; ++x) mask(x, y) = rows[static_cast<std::size_t>(r)][x] != '.';
  }
  return mask;
}

HullMask parse_text_mask(std::string_view text, const std::string& source) {
  return HullMask(parse_text_cells(text, source), source);
}

namespace {

// Reads PGM header tokens, skipping whitespace and '#' comments, tracking the line number.
class PgmHeaderReader {
 public:
  PgmHeaderReader(std::string_view bytes, const std::string& source)
      : bytes_(bytes), source_(source) {}

  int number(const char* what) {
    skip_space_and_comments();
    std::size_t start = pos_;
    long value = 0;
    while (pos_ < bytes_.size() && bytes_[pos_] >= '0' && bytes_[pos_] <= '9') {
      value = value * 10 + (bytes_[pos_] - '0');
      if (value > 1'000'000) throw InputError(source_, line_, fmt::format("{} is too large", what));
      ++pos_;
    }
    if (pos_ == start) {
      throw InputError(source_, line_, fmt::format("expected {} (a non-negative integer)", what));
    }
    return static_cast<int>(value);
  }
  std::size_t pos() const { return pos_; }
  int line() const { return line_; }
  void advance_one_whitespace() {
    if (pos_ < bytes_.size()) {
      if (bytes_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }

 private:
  void skip_space_and_comments() {
    while (pos_ < bytes_.size()) {
      const char c = bytes_[pos_];
      if (c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      } else if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        break;
      }
    }
  }
  std::string_view bytes_;
  const std::string& source_;
  std::size_t pos_ = 2;
  int line_ = 1;
};

}  // namespace

grid::Grid<std::uint8_t> parse_pgm_cells(std::string_view bytes, const std::string& source) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '5')) {
    throw InputError(source, 1,
                     fmt::format("not a greyscale PGM image (magic '{}'; expected 'P2' or 'P5')",
                                 escape_for_message(bytes.substr(0, 2))));
  }
  const bool binary = bytes[1] == '5';
  PgmHeaderReader reader(bytes, source);
  const int width = reader.number("the image width");
  const int height = reader.number("the image height");
  const int maxval = reader.number("the maximum grey value");
  if (width < 1 || height < 1 || width > kMaxGridSide || height > kMaxGridSide) {
    throw InputError(source, reader.line(),
                     fmt::format("image is {} × {}; each side must be within 1..{}", width, height,
                                 kMaxGridSide));
  }
  if (maxval < 1 || maxval > 65535) {
    throw InputError(source, reader.line(), "the maximum grey value must be within 1..65535");
  }
  grid::Grid<std::uint8_t> mask(width, height, 0);
  const auto total = static_cast<std::size_t>(width) * height;
  if (binary) {
    reader.advance_one_whitespace();
    const std::size_t bpp = maxval < 256 ? 1 : 2;
    if (bytes.size() - reader.pos() < total * bpp) {
      throw InputError(source, reader.line(),
                       fmt::format("pixel data is truncated: {} bytes for {} pixels",
                                   bytes.size() - reader.pos(), total));
    }
    for (std::size_t p = 0; p < total; ++p) {
      const std::size_t at = reader.pos() + p * bpp;
      int v = static_cast<unsigned char>(bytes[at]);
      if (bpp == 2) v = v * 256 + static_cast<unsigned char>(bytes[at + 1]);
      const int x = static_cast<int>(p % static_cast<std::size_t>(width));
      const int y = height - 1 - static_cast<int>(p / static_cast<std::size_t>(width));
      mask(x, y) = 2 * v > maxval;
    }
  } else {
    for (std::size_t p = 0; p < total; ++p) {
      const int v = reader.number("a grey value");
      if (v > maxval) {
        throw InputError(source, reader.line(),
                         fmt::format("grey value {} exceeds the maximum {}", v, maxval));
      }
      const int x = static_cast<int>(p % static_cast<std::size_t>(width));
      const int y = height - 1 - static_cast<int>(p / static_cast<std::size_t>(width));
      mask(x, y) = 2 * v > maxval;
    }
  }
  return mask;
}

HullMask parse_pgm_mask(std::string_view bytes, const std::string& source) {
  return HullMask(parse_pgm_cells(bytes, source), source);
}

grid::Grid<std::uint8_t> load_cell_map(const std::filesystem::path& path) {
  const std::string name = path.string();
  const std::string bytes = io::read_file(path, kMaxHullFileBytes, "the file");
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '0' && bytes[1] <= '9') {
    return parse_pgm_cells(bytes, name);
  }
  return parse_text_cells(bytes, name);
}

const HullMask& default_hull() {
  static const HullMask hull = parse_text_mask(detail::kDefaultHullText, "builtin:default");
  return hull;
}

bool is_hull_name(std::string_view spec) {
  return spec == "default" || spec == "builtin:default" || is_named_mesh_hull(spec);
}

HullMask load_hull(const std::filesystem::path& path) {
  const std::string name = path.string();
  if (name == "default" || name == "builtin:default") return default_hull();
  if (is_named_mesh_hull(name) || is_mesh_path(path)) return load_any_hull(path);
  // A word without an extension that names no file was most likely meant as a hull name.
  if (std::error_code ec; path.extension().empty() && !std::filesystem::exists(path, ec)) {
    throw InputError(name, 0, "no such hull file, and not a hull name (default, dtc)");
  }
  const std::string bytes = io::read_file(path, kMaxHullFileBytes, "the hull file");
  if (bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '0' && bytes[1] <= '9') {
    return parse_pgm_mask(bytes, name);
  }
  if (path.extension() == ".json") return parse_hull_json(bytes, name);
  return parse_text_mask(bytes, name);
}

std::string to_text_mask(const HullMask& hull) {
  std::string out;
  out.reserve(static_cast<std::size_t>((hull.width() + 1) * hull.height()));
  for (int y = hull.height() - 1; y >= 0; --y) {
    for (int x = 0; x < hull.width(); ++x) out += hull.is_hull(x, y) ? 'X' : '.';
    out += '\n';
  }
  return out;
}

}  // namespace hullinspect::world
