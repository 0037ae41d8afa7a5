#include "mesh_header_check.hpp"

#include <fmt/format.h>

#include <charconv>
#include <cstdint>
#include <cstring>
#include <vector>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/numbers.hpp"
#include "hullinspect/core/plural.hpp"

namespace hullinspect::world::detail {

namespace {

constexpr std::size_t kStlHeaderBytes = 84;  // 80-byte comment + uint32 facet count
constexpr std::size_t kStlFacetBytes = 50;   // normal, 3 vertices (12 floats), uint16 attribute

std::string_view trimmed(std::string_view s) {
  while (!s.empty() && std::strchr(" \t\r\n", s.front()) != nullptr) s.remove_prefix(1);
  while (!s.empty() && std::strchr(" \t\r\n", s.back()) != nullptr) s.remove_suffix(1);
  return s;
}

std::vector<std::string_view> words(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t pos = 0;
  while (pos < line.size()) {
    while (pos < line.size() && (line[pos] == ' ' || line[pos] == '\t')) ++pos;
    std::size_t end = pos;
    while (end < line.size() && line[end] != ' ' && line[end] != '\t') ++end;
    if (end > pos) out.push_back(line.substr(pos, end - pos));
    pos = end;
  }
  return out;
}

std::uint32_t little_u32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + k]);
  return v;
}

// Assimp reads an STL as binary unless it starts with "solid" and its size is not exactly that of
// a binary STL with the facet count of bytes 80–83; the same rule here.
void check_stl(std::string_view bytes, const std::string& source) {
  const bool sized_as_binary =
      bytes.size() >= kStlHeaderBytes &&
      bytes.size() == kStlHeaderBytes + kStlFacetBytes * std::uint64_t{little_u32(bytes, 80)};
  const std::string_view text = trimmed(bytes);
  if (text.starts_with("solid") && !sized_as_binary) {
    // ASCII: a file cut anywhere before its last line does not end with an endsolid line.
    const std::size_t last_line = text.rfind('\n');
    const auto last = words(text.substr(last_line == std::string_view::npos ? 0 : last_line + 1));
    if (last.empty() || last[0] != "endsolid") {
      throw InputError(source, 0,
                       "not a readable stl mesh (the ASCII STL does not end with an endsolid "
                       "line: truncated?)");
    }
    return;
  }
  if (bytes.size() < kStlHeaderBytes) {
    throw InputError(source, 0,
                     fmt::format("not a readable stl mesh (a binary STL has an {}-byte header; "
                                 "the file has {} bytes)",
                                 kStlHeaderBytes, bytes.size()));
  }
  const std::uint64_t facets = little_u32(bytes, 80);
  const std::uint64_t needed = kStlHeaderBytes + kStlFacetBytes * facets;
  if (bytes.size() < needed) {
    throw InputError(source, 0,
                     fmt::format("not a readable stl mesh (the binary STL declares {} facets ({} "
                                 "bytes) but has {} bytes: truncated?)",
                                 facets, needed, bytes.size()));
  }
}

struct PlyProperty {
  std::size_t size = 0;        // bytes of a scalar, or of one list item
  std::size_t count_size = 0;  // bytes of a list's count; 0 for a scalar
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

std::size_t ply_type_size(std::string_view type) {
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8") return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16") return 2;
  if (type == "int" || type == "uint" || type == "float" || type == "int32" || type == "uint32" ||
      type == "float32") {
    return 4;
  }
  if (type == "double" || type == "float64") return 8;
  return 0;
}

[[noreturn]] void refuse_ply(const std::string& source, const std::string& why) {
  throw InputError(source, 0, fmt::format("not a readable ply mesh ({})", why));
}

// Reads the unsigned integer of `bytes` at `at` (`size` bytes, the file's byte order).
std::uint64_t ply_unsigned(std::string_view bytes, std::size_t at, std::size_t size, bool big) {
  std::uint64_t v = 0;
  for (std::size_t k = 0; k < size; ++k) {
    v = (v << 8) | static_cast<unsigned char>(bytes[at + (big ? k : size - 1 - k)]);
  }
  return v;
}

void check_ply(std::string_view bytes, const std::string& source) {
  std::vector<PlyElement> elements;
  std::string format;
  std::size_t pos = 0;
  bool ended = false;
  while (pos < bytes.size() && !ended) {
    std::size_t end = bytes.find('\n', pos);
    if (end == std::string_view::npos) end = bytes.size();
    const std::vector<std::string_view> w = words(trimmed(bytes.substr(pos, end - pos)));
    pos = end + 1;
    if (w.empty()) continue;
    if (w[0] == "end_header") {
      ended = w.size() == 1;
    } else if (w[0] == "format" && w.size() >= 2) {
      format = std::string(w[1]);
    } else if (w[0] == "element" && w.size() == 3) {
      PlyElement e;
      e.name = escape_for_message(w[1], 40);
      std::uint64_t count = 0;
      const auto [end_of_count, ec] =
          std::from_chars(w[2].data(), w[2].data() + w[2].size(), count);
      // Assimp keeps counts in 32 bits; a larger one would wrap.
      if (ec != std::errc() || end_of_count != w[2].data() + w[2].size() || count > 0xffffffffu) {
        refuse_ply(source, fmt::format("element {} has count '{}'; expected an integer in [0, "
                                       "4294967295]",
                                       e.name, escape_for_message(w[2], 40)));
      }
      e.count = count;
      elements.push_back(e);
    } else if (w[0] == "property" && !elements.empty()) {
      PlyProperty p;
      if (w.size() >= 4 && w[1] == "list") {
        p.count_size = ply_type_size(w[2]);
        p.size = ply_type_size(w[3]);
      } else if (w.size() >= 2) {
        p.size = ply_type_size(w[1]);
      }
      elements.back().properties.push_back(p);
    }
  }
  if (!ended) refuse_ply(source, "its header has no end_header line");
  const std::string_view body = pos <= bytes.size() ? bytes.substr(pos) : std::string_view();
  if (format == "ascii") {
    // One line per item: every count must fit in the lines that follow, together.
    std::uint64_t lines = 0;
    for (std::size_t at = 0; at < body.size();) {
      std::size_t end = body.find('\n', at);
      if (end == std::string_view::npos) end = body.size();
      if (!trimmed(body.substr(at, end - at)).empty()) ++lines;
      at = end + 1;
    }
    std::uint64_t declared = 0;
    for (const PlyElement& e : elements) {
      declared += e.count;
      if (declared > lines) {
        refuse_ply(source, fmt::format("element {}: {} declared, but the data ends after "
                                       "{}: truncated?",
                                       e.name, e.count,
                                       plural(static_cast<long long>(lines - (declared - e.count)),
                                              "line")));
      }
    }
    return;
  }
  if (format != "binary_little_endian" && format != "binary_big_endian") return;  // Assimp's say
  const bool big = format == "binary_big_endian";
  std::size_t at = 0;
  for (const PlyElement& e : elements) {
    // At least the scalars and the lists' counts of every item must fit, before any is walked.
    std::uint64_t least = 0;
    for (const PlyProperty& p : e.properties) least += p.count_size > 0 ? p.count_size : p.size;
    if (least > 0 && e.count > (body.size() - at) / least) {
      refuse_ply(source, fmt::format("element {}: {} declared, more than the {} bytes after "
                                     "the header hold: truncated?",
                                     e.name, e.count, body.size()));
    }
    if (least == 0) continue;  // nothing to walk
    for (std::uint64_t item = 0; item < e.count; ++item) {
      for (const PlyProperty& p : e.properties) {
        std::uint64_t size = p.size;
        if (p.count_size > 0) {
          if (at + p.count_size > body.size())
            size = body.size();  // refused just below
          else {
            size = ply_unsigned(body, at, p.count_size, big) * p.size;
            at += p.count_size;
          }
        }
        if (size > body.size() - at) {
          refuse_ply(source, fmt::format("element {}: the data ends inside number {} of {}: "
                                         "truncated?",
                                         e.name, item + 1, e.count));
        }
        at += size;
      }
    }
  }
}

}  // namespace

void check_mesh_counts(std::string_view bytes, const std::string& format,
                       const std::string& source) {
  if (format == "ply" || bytes.starts_with("ply")) {
    check_ply(bytes, source);
  } else if (format == "stl") {
    check_stl(bytes, source);
  }
}

}  // namespace hullinspect::world::detail
