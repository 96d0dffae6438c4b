#pragma once
// The range check of every number on the tools' command lines: CLI::Range lets NaN through (a
// comparison with NaN is false), and --max-gap nan or --duration inf ran (issue 28, item 14).
// This one refuses what is not a finite number, then checks the range, and says both.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdlib>
#include <string>

namespace planter::config {

inline CLI::Validator finite_range(double min, double max) {
  CLI::Validator v(
      [min, max](std::string& text) -> std::string {
        char* end = nullptr;
        const double value = std::strtod(text.c_str(), &end);
        if (text.empty() || end != text.c_str() + text.size() || !std::isfinite(value))
          return "'" + text + "' is not a finite number";
        if (value < min || value > max)
          return "'" + text + "' is outside " + CLI::detail::to_string(min) + " to " +
                 CLI::detail::to_string(max);
        return "";
      },
      "NUMBER in [" + CLI::detail::to_string(min) + " - " + CLI::detail::to_string(max) + "]");
  return v;
}

// A count or an index read into an unsigned number: checked as text first, where "-1" would
// otherwise wrap around to the largest value (issue 53, item 14).
inline CLI::Validator whole_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const bool digits = !text.empty() && text.size() <= 18 &&
                            text.find_first_not_of("0123456789") == std::string::npos;
        return digits ? "" : "'" + text + "' is not a whole number from 0";
      },
      "WHOLE NUMBER from 0");
}

}  // namespace planter::config
