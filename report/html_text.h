#pragma once
// User strings (scenario names, file paths, board names) placed in a report's HTML.
#include <string>
#include <string_view>

namespace planter::report {

// Escapes & < > " ' so a name such as "</script>" is shown as text, never parsed as markup.
std::string html_escape(std::string_view text);
// A file's path, escaped, that a narrow screen may break after each '/' (<wbr>) and nowhere
// inside a folder's name.
std::string html_path(std::string_view path);

// Every report's head: UTF-8, and laid out for the screen it is read on (a 390 px phone too,
// instead of a 980 px page shown at 40 %). A table keeps its words whole and scrolls sideways in
// its own box; running text breaks a word only when it is longer than the line (a path).
inline constexpr const char* kReportHead =
    "<meta charset='utf-8'><meta name='viewport' content='width=device-width, initial-scale=1'>"
    "<style>table{display:block;overflow-x:auto;max-width:100%}svg,img{max-width:100%;"
    "height:auto}body{padding:0 8px;overflow-wrap:break-word}td,th{overflow-wrap:normal}"
    "pre{overflow-x:auto}</style>";

// The pages that are mostly tables of figures (the sweep's, the sensitivity analysis'):
// numbers right-aligned in ruled cells.
inline constexpr const char* kTablePageStyle =
    "<style>body{font-family:sans-serif;max-width:1000px;margin:auto}table{border-collapse:"
    "collapse}td,th{border:1px solid #ccc;padding:2px 6px;text-align:right}</style>";

// A figure for a reader: v with the given number of decimals ("91.21").
std::string fixed(double v, int decimals);
// A figure in a printf format of one double ("%.3g" gives "0.0123"), for a page's text.
std::string formatted(const char* printf_format, double v);

}  // namespace planter::report
