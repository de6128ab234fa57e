#pragma once
// Numbers in text files (OBJ, ascii PLY): whole tokens read correctly rounded, whatever the locale.

#include <string_view>

namespace graspecmf {

// Reads the whole token (an optional leading '+' allowed) as a correctly rounded double into out;
// false if it is empty or any character is left. Underflow gives a subnormal or zero, overflow
// ±infinity (both returned as read).
bool parse_number(std::string_view token, double& out);

}  // namespace graspecmf
