#include "hullinspect/experiment/csv.hpp"

#include "hullinspect/core/numbers.hpp"

#include <fmt/format.h>

#include "hullinspect/core/errors.hpp"

namespace hullinspect::experiment {

std::string csv_field(std::string_view value) {
  if (value.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(value);
  std::string out = "\"";
  for (char c : value) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
  return out;
}

std::string csv_line(const std::vector<std::string>& fields) {
  std::string line;
  for (std::size_t i = 0; i < fields.size(); ++i) {
    if (i > 0) line += ',';
    line += csv_field(fields[i]);
  }
  return line;
}

std::optional<std::vector<std::string>> split_csv_line(std::string_view line) {
  std::vector<std::string> fields;
  std::string field;
  std::size_t i = 0;
  while (true) {
    field.clear();
    if (i < line.size() && line[i] == '"') {
      ++i;
      while (true) {
        if (i >= line.size()) return std::nullopt;  // unterminated quote
        if (line[i] == '"') {
          if (i + 1 < line.size() && line[i + 1] == '"') {
            field += '"';
            i += 2;
            continue;
          }
          ++i;
          break;
        }
        field += line[i++];
      }
      if (i < line.size() && line[i] != ',') return std::nullopt;
    } else {
      while (i < line.size() && line[i] != ',') {
        if (line[i] == '"') return std::nullopt;
        field += line[i++];
      }
    }
    fields.push_back(field);
    if (i >= line.size()) break;
    ++i;  // the comma
  }
  return fields;
}

int CsvTable::find_column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  return -1;
}

int CsvTable::column(const std::string& name, const std::string& source) const {
  for (std::size_t i = 0; i < header.size(); ++i) {
    if (header[i] == name) return static_cast<int>(i);
  }
  throw InputError(source, 1, fmt::format("has no column '{}'", name));
}

CsvTable parse_csv(std::string_view text, const std::string& source) {
  CsvTable table;
  int line_number = 0;
  std::size_t start = 0;
  while (start < text.size()) {
    ++line_number;
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      throw InputError(source, line_number, "the last line is not terminated (a torn write?)");
    }
    const auto fields = split_csv_line(text.substr(start, end - start));
    start = end + 1;
    if (!fields) throw InputError(source, line_number, "malformed CSV quoting");
    if (line_number == 1) {
      table.header = *fields;
    } else if (fields->size() != table.header.size()) {
      throw InputError(
          source, line_number,
          fmt::format("has {} fields; the header has {}", fields->size(), table.header.size()));
    } else {
      table.rows.push_back(*fields);
    }
  }
  if (line_number == 0) throw InputError(source, 0, "is empty (no header)");
  return table;
}

int csv_int(const std::string& field, const std::string& source, int line,
            const std::string& column, int min, int max) {
  try {
    return parse_integer<int>(field, min, max);
  } catch (const NumberError& e) {
    throw InputError(source, line, fmt::format("{}: {}", column, e.what()));
  }
}

double csv_seconds(const std::string& field, const std::string& source, int line,
                   const std::string& column) {
  try {
    return parse_real(field, 0, 1e15);
  } catch (const NumberError& e) {
    throw InputError(source, line, fmt::format("{}: {}", column, e.what()));
  }
}

}  // namespace hullinspect::experiment
