#pragma once
// User strings (scenario names, file paths, board names) placed in a report's HTML.
#include <string>
#include <string_view>

namespace planter::report {

// Escapes & < > " ' so a name such as "</script>" is shown as text, never parsed as markup.
std::string html_escape(std::string_view text);

// A figure for a reader: v with the given number of decimals ("91.21").
std::string fixed(double v, int decimals);

}  // namespace planter::report
