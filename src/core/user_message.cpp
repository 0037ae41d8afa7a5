// The one-line message a user sees for an error, shared by the CLI and the Python module.

#include "hullinspect/core/errors.hpp"

namespace hullinspect {

std::string option_name(const std::string& parameter) {
  std::string name = parameter;
  if (auto dot = name.rfind('.'); dot != std::string::npos) name = name.substr(dot + 1);
  for (char& c : name) {
    if (c == '_') c = '-';
  }
  // The library checks a list of start cells ("starts"); each is one --start on the command line.
  if (name == "starts") return "--start";
  return "--" + name;
}

std::string user_message(const std::exception& error) {
  if (const auto* p = dynamic_cast<const ParameterError*>(&error)) {
    return option_name(p->name()) + ": " + p->problem();
  }
  return error.what();
}

}  // namespace hullinspect
