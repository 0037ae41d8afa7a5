#pragma once
// Minimal RFC 4180 CSV for result tables: fields are quoted only when they contain a comma, a quote
// or a line break; one record per line.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace hullinspect::experiment {

/// The field as written in a CSV line (quoted if needed).
std::string csv_field(std::string_view value);

/// Joins fields into one line (no line break).
std::string csv_line(const std::vector<std::string>& fields);

/// Splits one line into fields; empty when the quoting is malformed.
std::optional<std::vector<std::string>> split_csv_line(std::string_view line);

/// A whole CSV file held in memory, with columns looked up by name.
struct CsvTable {
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  /// Index of a column; throws InputError naming `source` when it is missing.
  int column(const std::string& name, const std::string& source) const;
  /// Index of a column, or −1 when it is missing (optional columns of newer versions).
  int find_column(const std::string& name) const;
};

/// A field read as an integer in [min, max] through the shared number parser (core/numbers.hpp);
/// throws InputError naming `source`, the line and `column` otherwise.
int csv_int(const std::string& field, const std::string& source, int line,
            const std::string& column, int min = 0, int max = 1 << 30);

/// A time field in seconds (T_c, T_m and their bounds; whole numbers without --speed): a real in
/// [0, 1e15], read like csv_int.
double csv_seconds(const std::string& field, const std::string& source, int line,
                   const std::string& column);

/// Parses a complete CSV file (every line ends with a line break). Throws InputError naming
/// `source` and the line for a malformed row or a row with the wrong number of fields.
CsvTable parse_csv(std::string_view text, const std::string& source);

}  // namespace hullinspect::experiment
