#pragma once
// The error of an output that cannot be written although the input was fine.

#include <string>

#include "hullinspect/core/errors.hpp"

namespace hullinspect {

/// Valid input, but the environment failed: an output that cannot be written, flushed or renamed
/// into place (a full disk, a lost permission). The CLI exits 1, not 2: the input was fine.
/// what() reads "FILE: problem".
class OutputError : public Error {
 public:
  OutputError(const std::string& file, const std::string& problem) : Error(file + ": " + problem) {}
};

}  // namespace hullinspect
