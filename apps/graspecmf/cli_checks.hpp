#pragma once
// Option validators shared by the commands: a number must be finite (CLI11 reads "nan" and "inf"
// as numbers), and positive where a scale or a size is meant.

#include <CLI/CLI.hpp>
#include <cmath>
#include <string>

namespace graspecmf::apps {

// Accepts a finite number; "nan", "inf" and non-numbers get one clear message.
inline const CLI::Validator kFiniteNumber(
    [](std::string& text) -> std::string {
      double value = 0;
      if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value)) {
        return "must be a finite number, not '" + text + "'";
      }
      return "";
    },
    "FINITE");

// Accepts a finite number above 0.
inline const CLI::Validator kPositiveFiniteNumber = kFiniteNumber & CLI::PositiveNumber;

}  // namespace graspecmf::apps
