#pragma once
// Numbers on the command line go through the shared parser (core/numbers.hpp), never through
// CLI11's own conversion alone: CLI11 turns "-1" into 2^64 - 1 for an unsigned option and "1e23"
// into a saturated integer. require_exact_numbers() attaches the parser to every numeric option of
// every subcommand (by CLI11's type name INT, UINT or FLOAT), so a new option is covered without
// anyone remembering to; options with a narrower accepted range add integer_in()/real_in().

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

#include "hullinspect/grid/cell.hpp"

namespace hullinspect::cli {

/// Refuses values that are not integers in [min, max] with the shared parser's one-line message.
CLI::Validator integer_in(std::int64_t min, std::int64_t max);
/// Refuses values that are no int at all naming [min, max], the option's range; an int outside it
/// is left to the command's own check, whose message gives the reason.
CLI::Validator integer_text_in(int min, int max);
/// Refuses values that are not finite reals in [min, max].
CLI::Validator real_in(double min, double max);

/// A check that accepts everything and marks an option whose value a mission declaration parses
/// in its own range: require_exact_numbers() leaves such options alone.
CLI::Validator declared_value_marker();

/// Attaches the exact parser to every INT (int range), UINT (uint64 range) and FLOAT (finite,
/// ±kRealLimit) option of `app` and its subcommands that has no narrower check of its own (a
/// declared_value_marker()). Call after every command is registered.
void require_exact_numbers(CLI::App& app);

/// A CLI11 parse error as one of our messages: "Could not convert: --uavs,-n = abc" becomes
/// "--uavs: 'abc' is not a valid value"; every message ends in " (see --help)".
std::string parse_error_message(const CLI::ParseError& e);

}  // namespace hullinspect::cli
