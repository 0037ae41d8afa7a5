#include "hullinspect/core/errors.hpp"

#include <utility>

namespace hullinspect {

namespace {
std::string located(const std::string& file, int line, const std::string& problem) {
  if (line > 0) return file + ":" + std::to_string(line) + ": " + problem;
  return file + ": " + problem;
}
}  // namespace

InputError::InputError(std::string file, int line, const std::string& problem)
    : Error(located(file, line, problem)), file_(std::move(file)), line_(line) {}

ParameterError::ParameterError(std::string name, const std::string& problem)
    : Error(name + ": " + problem), name_(std::move(name)), problem_(problem) {}

}  // namespace hullinspect
