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

// The first line of a library's message (LibTorch, assimp, CGAL), for a one-line Error; "unknown
// error" when that line is empty.
inline std::string first_line(const std::string& text) {
  const std::string line = text.substr(0, text.find('\n'));
  return line.empty() ? std::string("unknown error") : line;
}

}  // namespace graspecmf
