#pragma once
// Inline SVG line plots for the self-contained HTML reports (planter-sim, planter-dem).
#include <string>
#include <vector>

namespace planter::report {

struct PlotLine {
  const std::vector<double>* y;
  const char* colour;
  const char* label;
  const std::vector<double>* x = nullptr;  // its own x values; nullptr = the plot's shared x
};

// One plot 860x220 px: title [unit], y grid from y_min to y_max, x from the shared x values.
std::string svg_plot(const std::string& title, const std::string& unit, const std::string& x_label,
                     const std::vector<double>& x, const std::vector<PlotLine>& lines, double y_min,
                     double y_max);

}  // namespace planter::report
