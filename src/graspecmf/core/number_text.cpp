#include "graspecmf/core/number_text.hpp"

#include <charconv>
#include <cstdlib>
#include <string>
#include <system_error>

namespace graspecmf {

bool parse_number(std::string_view token, double& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const char* end = token.data() + token.size();
  const auto result = std::from_chars(token.data(), end, out);
  if (result.ptr != end) return false;
  if (result.ec == std::errc::result_out_of_range) {
    out = std::strtod(std::string(token).c_str(), nullptr);
    return true;
  }
  return result.ec == std::errc();
}

}  // namespace graspecmf
