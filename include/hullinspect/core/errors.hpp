#pragma once
// Typed errors thrown by library code. The CLI turns each into one line on stderr and an exit status;
// nothing below apps/ prints or exits.

#include <stdexcept>
#include <string>

namespace hullinspect {

/// Base of every error hullinspect throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file that cannot be read or does not follow its format. what() reads "FILE:LINE: problem"
/// (or "FILE: problem" when no line applies).
class InputError : public Error {
 public:
  InputError(std::string file, int line, const std::string& problem);
  const std::string& file() const { return file_; }
  int line() const { return line_; }

 private:
  std::string file_;
  int line_;
};

/// A parameter outside its accepted range. `name` is the parameter's name as the user spells it in
/// configs ("s2", "p_tp"); the CLI maps it to its option ("--s2"). what() reads "name: problem".
class ParameterError : public Error {
 public:
  ParameterError(std::string name, const std::string& problem);
  const std::string& name() const { return name_; }
  const std::string& problem() const { return problem_; }

 private:
  std::string name_;
  std::string problem_;
};

/// A planner or solver broke a rule of the model (e.g. moved a UAV off the grid): a bug, not bad input.
class LogicError : public Error {
 public:
  using Error::Error;
};

/// "--p-tp" for the parameter "p_tp"; "--algorithm" for "algorithm"; "--r1" for "part-tsp.r1".
std::string option_name(const std::string& parameter);

/// The one line the CLI prints after "hullinspect: " (and the Python module raises): a
/// ParameterError as "--option: problem", anything else as what().
std::string user_message(const std::exception& error);

}  // namespace hullinspect
