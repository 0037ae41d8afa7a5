#pragma once
// The trace reader's field checks, shared by the files that check a trace (trace_reader.cpp,
// trace_motion.cpp): every failure throws InputError naming the file and the field.

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <cstdint>
#include <limits>
#include <string>
#include <string_view>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::io::detail {

using nlohmann::json;

// Checks one trace; every failure names the field, e.g. "frames[3].u[7]: expected 1 or 2".
class TraceChecker {
 public:
  explicit TraceChecker(std::string source) : source_(std::move(source)) {}

  [[noreturn]] void fail(const std::string& where, const std::string& problem) const {
    throw InputError(source_, 0, where + ": " + problem);
  }

  const json& field(const json& object, const std::string& where, const char* key) const {
    auto it = object.find(key);
    if (it == object.end()) fail(where.empty() ? key : where + "." + key, "missing");
    return *it;
  }

  std::int64_t integer(const json& v, const std::string& where, std::int64_t lo,
                       std::int64_t hi) const {
    if (!v.is_number_integer()) fail(where, "expected an integer");
    if (v.is_number_unsigned() &&
        v.get<std::uint64_t>() >
            static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
      fail(where, fmt::format("{} is outside [{}, {}]", v.dump(), lo, hi));
    }
    const auto i = v.get<std::int64_t>();
    if (i < lo || i > hi) fail(where, fmt::format("{} is outside [{}, {}]", i, lo, hi));
    return i;
  }

  const json& array(const json& v, const std::string& where) const {
    if (!v.is_array()) fail(where, "expected an array");
    return v;
  }

  const json& object(const json& v, const std::string& where) const {
    if (!v.is_object()) fail(where, "expected an object");
    return v;
  }

  // `height` strings of `width` characters from `alphabet`.
  void rows(const json& v, const std::string& where, int width, int height,
            std::string_view alphabet) const {
    array(v, where);
    if (v.size() != static_cast<std::size_t>(height)) {
      fail(where, fmt::format("expected {} rows (the grid height), got {}", height, v.size()));
    }
    for (std::size_t y = 0; y < v.size(); ++y) {
      const auto at = fmt::format("{}[{}]", where, y);
      if (!v[y].is_string()) fail(at, "expected a string");
      const auto& row = v[y].get_ref<const std::string&>();
      if (row.size() != static_cast<std::size_t>(width)) {
        fail(at, fmt::format("expected {} characters (the grid width), got {}", width, row.size()));
      }
      for (std::size_t x = 0; x < row.size(); ++x) {
        if (alphabet.find(row[x]) == std::string_view::npos) {
          fail(at,
               fmt::format("character {} is '{}', expected one of \"{}\"", x, row[x], alphabet));
        }
      }
    }
  }

  void cell(const json& v, const std::string& where, int width, int height) const {
    if (!v.is_array() || v.size() != 2) fail(where, "expected [x, y]");
    integer(v[0], where + "[0]", 0, width - 1);
    integer(v[1], where + "[1]", 0, height - 1);
  }

 private:
  std::string source_;
};

}  // namespace hullinspect::io::detail
