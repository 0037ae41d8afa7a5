#include "number_options.hpp"

#include <fmt/format.h>

#include <limits>

#include "hullinspect/core/errors.hpp"
#include "hullinspect/core/integer_of_range.hpp"
#include "hullinspect/core/numbers.hpp"

namespace hullinspect::cli {

namespace {

template <class Parse>
CLI::Validator number_validator(Parse parse) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
          return {};
        } catch (const NumberError& e) {
          return e.what();
        }
      },
      "");
}

constexpr const char* kDeclaredValue = "declared-value";

bool has_declared_value(CLI::Option& option) {
  try {
    option.get_validator(kDeclaredValue);
    return true;
  } catch (const CLI::OptionNotFound&) {
    return false;
  }
}

void attach(CLI::App& app) {
  for (CLI::Option* option : app.get_options()) {
    if (has_declared_value(*option)) continue;
    const std::string type = option->get_type_name();
    if (type == "INT") {
      option->check(number_validator([](const std::string& t) { parse_integer<int>(t); }));
    } else if (type == "UINT") {
      option->check(
          number_validator([](const std::string& t) { parse_integer<std::uint64_t>(t); }));
    } else if (type == "FLOAT") {
      option->check(number_validator([](const std::string& t) { parse_real(t); }));
    }
  }
  for (CLI::App* sub : app.get_subcommands({})) attach(*sub);
}

}  // namespace

CLI::Validator declared_value_marker() {
  return CLI::Validator([](std::string&) { return std::string(); }, "", kDeclaredValue);
}

CLI::Validator integer_in(std::int64_t min, std::int64_t max) {
  return number_validator([=](const std::string& t) { parse_integer<std::int64_t>(t, min, max); });
}

CLI::Validator integer_text_in(int min, int max) {
  return number_validator([=](const std::string& t) { parse_integer_of_range<int>(t, min, max); });
}

CLI::Validator real_in(double min, double max) {
  return number_validator([=](const std::string& t) { parse_real(t, min, max); });
}

void require_exact_numbers(CLI::App& app) {
  attach(app);
}

std::string parse_error_message(const CLI::ParseError& e) {
  std::string message = e.what();
  const std::string prefix = "Could not convert: ";
  if (message.rfind(prefix, 0) == 0) {
    const auto eq = message.find(" = ");
    std::string option = message.substr(prefix.size(), eq - prefix.size());
    option = option.substr(0, option.find(','));
    const std::string value = eq == std::string::npos ? "" : message.substr(eq + 3);
    message = option + ": '" + value + "' is not a valid value";
  }
  return message + " (see --help)";
}

}  // namespace hullinspect::cli
