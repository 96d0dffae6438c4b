#include "sim/report/svg_plot.h"

#include <algorithm>
#include <sstream>

namespace planter::report {

std::string svg_plot(const std::string& title, const std::string& unit, const std::string& x_label,
                     const std::vector<double>& x, const std::vector<PlotLine>& lines, double y_min,
                     double y_max) {
  const double w = 860, h = 220, left = 60, right = 10, top = 24, bottom = 30;
  const double x0 = x.empty() ? 0 : x.front(), x1 = x.empty() ? 1 : std::max(x.back(), x0 + 1e-9);
  if (y_max <= y_min) y_max = y_min + 1.0;
  auto px = [&](double v) { return left + (v - x0) / (x1 - x0) * (w - left - right); };
  auto py = [&](double v) {
    return top +
           (1.0 - (std::clamp(v, y_min, y_max) - y_min) / (y_max - y_min)) * (h - top - bottom);
  };
  std::ostringstream s;
  s.precision(5);
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h << "'>"
    << "<rect width='100%' height='100%' fill='white'/>"
    << "<text x='" << left << "' y='16' font-size='13' font-family='sans-serif'>" << title << " ["
    << unit << "]</text>";
  for (int i = 0; i <= 4; ++i) {
    const double v = y_min + (y_max - y_min) * i / 4.0;
    s << "<line x1='" << left << "' x2='" << w - right << "' y1='" << py(v) << "' y2='" << py(v)
      << "' stroke='#ddd'/><text x='4' y='" << py(v) + 4
      << "' font-size='10' font-family='sans-serif'>" << v << "</text>";
  }
  s << "<text x='" << w - 160 << "' y='" << h - 6 << "' font-size='10' font-family='sans-serif'>"
    << x_label << ", " << x0 << "-" << x1 << "</text>";
  double lx = left + 200;
  for (const PlotLine& line : lines) {
    const std::vector<double>& lxs = line.x ? *line.x : x;
    s << "<polyline fill='none' stroke-width='1.2' stroke='" << line.colour << "' points='";
    const std::size_t stride = std::max<std::size_t>(1, lxs.size() / 1500);
    for (std::size_t i = 0; i < lxs.size() && i < line.y->size(); i += stride)
      s << px(lxs[i]) << ',' << py((*line.y)[i]) << ' ';
    s << "'/><text x='" << lx << "' y='16' font-size='11' fill='" << line.colour
      << "' font-family='sans-serif'>" << line.label << "</text>";
    lx += 150;
  }
  s << "</svg>";
  return s.str();
}

}  // namespace planter::report
