#pragma once
// User strings (scenario names, file paths, board names) placed in a report's HTML.
#include <string>
#include <string_view>

namespace planter::report {

// Escapes & < > " ' so a name such as "</script>" is shown as text, never parsed as markup.
std::string html_escape(std::string_view text);

}  // namespace planter::report
