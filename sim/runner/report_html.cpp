// A self-contained HTML report: numbers, assumptions and inline SVG plots; no network.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "sim/report/html_text.h"
#include "sim/report/svg_plot.h"
#include "sim/runner/recording_writer.h"

namespace planter::sim {
namespace {

using report::PlotLine;

std::string svg_plot(const std::string& title, const std::string& unit,
                     const std::vector<double>& t, const std::vector<PlotLine>& lines, double y_min,
                     double y_max) {
  return report::svg_plot(title, unit, "time [s]", t, lines, y_min, y_max);
}

std::string histogram(const std::string& title, const std::vector<double>& values, double lo,
                      double hi, int bins) {
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  for (double v : values) {
    const int b = std::clamp(static_cast<int>((v - lo) / (hi - lo) * bins), 0, bins - 1);
    ++counts[static_cast<std::size_t>(b)];
  }
  const int top = std::max(1, *std::max_element(counts.begin(), counts.end()));
  std::ostringstream s;
  const double w = 420, h = 200, bw = (w - 40) / bins;
  s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << w << "' height='" << h
    << "'><rect width='100%' height='100%' fill='white'/>"
    << "<text x='40' y='14' font-size='12' font-family='sans-serif'>" << title << "</text>";
  for (int b = 0; b < bins; ++b) {
    const double bh = (h - 50) * counts[static_cast<std::size_t>(b)] / top;
    s << "<rect x='" << 40 + b * bw << "' y='" << h - 30 - bh << "' width='" << bw - 1
      << "' height='" << bh << "' fill='#4a7'/>";
  }
  s << "<text x='40' y='" << h - 14 << "' font-size='10' font-family='sans-serif'>" << lo
    << "</text><text x='" << w - 30 << "' y='" << h - 14
    << "' font-size='10' font-family='sans-serif'>" << hi << "</text></svg>";
  return s.str();
}

}  // namespace

std::string report_html(const Scenario& sc, const Summary& s, const ReportSeries& r,
                        const SeedlingProcess& seedlings) {
  using report::html_escape;
  std::ostringstream out;
  std::vector<double> tilts, spacing, peaks;
  double last_x = -1;
  std::vector<double> xs;
  for (const Seedling& sd : seedlings.seedlings()) {
    if (!sd.planted) continue;
    tilts.push_back(sd.tilt_deg);
    peaks.push_back(sd.peak_force_N);
    xs.push_back(sd.x_m);
  }
  std::sort(xs.begin(), xs.end());
  for (double x : xs) {
    if (last_x >= 0) spacing.push_back((x - last_x) * 1000);
    last_x = x;
  }
  const double ceiling = s.clamp_ceiling_N;
  std::vector<double> ceiling_line(r.t.size(), ceiling);
  std::vector<double> sigma_line(r.t.size(), s.sigma_target);
  out << "<!doctype html><html><head><meta charset='utf-8'><title>planter-sim: "
      << html_escape(s.scenario) << "</title>"
      << "<style>body{font-family:sans-serif;max-width:900px;margin:20px auto}td{padding:2px 10px}"
      << "table{border-collapse:collapse}tr:nth-child(even){background:#f4f4f4}</style></"
         "head><body>"
      << "<h1>Simulated run: " << html_escape(s.scenario) << "</h1><p>Scenario <code>"
      << html_escape(sc.file) << "</code>, board <code>" << html_escape(sc.board.name)
      << "</code>, seed " << sc.seed << ".</p><h2>Figures</h2><table>";
  auto row = [&](const char* name, double v, const char* unit, const char* paper) {
    out << "<tr><td>" << name << "</td><td><b>" << v << "</b> " << unit << "</td><td>" << paper
        << "</td></tr>";
  };
  row("uprightness", s.uprightness_pct, "%", "paper: 94.8 % predicted, 93.86 % field");
  row("damage rate", s.damage_pct, "%", "paper: 3 % predicted, 2.76 % field");
  row("plant spacing, mean", s.spacing_mean_mm, "mm", "agronomy: 20-30 mm");
  row("plant spacing, CV", s.spacing_cv_pct, "%", "");
  row("seedlings planted", s.seedlings_planted, "", "paper: 96-100 per 3 m plot");
  row("true sigma, mean", s.sigma_true_mean, "", "target 1.5");
  row("true sigma, RMS error", s.sigma_true_rms_error_pct, "%", "goal < 2 %");
  row("controller's sigma, RMS error", s.sigma_ctrl_rms_error_pct, "%", "");
  row("clamp force, mean", s.clamp_force_mean_N, "N", "paper: 90-92 N");
  row("clamp force, max", s.clamp_force_max_N, "N", "must stay below the ceiling");
  row("clamp ceiling", s.clamp_ceiling_N, "N", "below 127.2 N, the weakest measured seedling");
  row("depth, mean", s.depth_mean_mm, "mm", "target 102 mm");
  row("depth, RMS error", s.depth_rms_error_mm, "mm", "goal within 5 mm");
  row("CAN bus load", s.can_bus_load_pct, "%", "");
  row("real-time factor", s.realtime_factor, "x", "");
  out << "</table><p>Seedlings per 3 m plot: ";
  for (int c : s.plot_counts) out << c << ' ';
  out << "</p><h2>Plots</h2>"
      << svg_plot("Ground speed", "m/s", r.t,
                  {{&r.v_ground, "#000", "true"}, {&r.v_wheel, "#d60", "soil wheel"}}, 0, 0.1)
      << svg_plot("Sigma = R*omega/v (v > 0.02 m/s)", "-", r.t,
                  {{&r.sigma_true, "#06c", "true"},
                   {&r.sigma_ctrl, "#d60", "controller"},
                   {&sigma_line, "#999", "target"}},
                  1.2, 1.8)
      << svg_plot("Disc speed", "rad/s", r.t,
                  {{&r.omega, "#06c", "measured"}, {&r.omega_cmd, "#d60", "command"}}, 0, 0.5)
      << svg_plot("Clamp force", "N", r.t,
                  {{&r.clamp_force, "#06c", "true"},
                   {&r.clamp_force_cmd, "#d60", "set-point"},
                   {&ceiling_line, "#c00", "ceiling"}},
                  0, 140)
      << svg_plot("Furrow depth", "mm", r.t,
                  {{&r.depth, "#06c", "true"}, {&r.depth_cmd, "#d60", "command"}}, 0, 170)
      << "<h2>Seedling outcomes</h2>"
      << histogram("tilt from vertical, + top forward [deg]; lodged (+-90) in the end bins", tilts,
                   -30, 30, 60)
      << histogram("spacing [mm]", spacing, 0, 80, 40)
      << histogram("peak radial force in the nip [N]", peaks, 60, 140, 40)
      << "<h2>Model assumptions</h2><p>Written from the configuration that ran.</p><ul>";
  for (const std::string& a : s.assumptions) out << "<li>" << html_escape(a) << "</li>";
  out << "</ul></body></html>";
  return out.str();
}

}  // namespace planter::sim
