#pragma once
// The one exception type graspecmf throws for bad input or failed I/O; its what() is a single
// human-readable line that the command-line front end prints as "error: <what>".

#include <stdexcept>
#include <string>

namespace graspecmf {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace graspecmf
