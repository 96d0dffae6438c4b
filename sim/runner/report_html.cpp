// A self-contained HTML report: numbers, assumptions and charts (dygraphs, inlined); no network.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "report/chart.h"
#include "report/html_text.h"
#include "sim/runner/recording_writer.h"

namespace planter::sim {
namespace {

using report::ChartSpec;
using report::html_escape;
using report::Line;
using report::Marker;

// What the planted seedlings show: each one's tilt and peak force, and the gaps between them
// along the row.
struct Planted {
  std::vector<double> tilts_deg, spacing_mm, peaks_N;
};

Planted planted_of(const SeedlingProcess& seedlings) {
  Planted p;
  std::vector<double> xs;
  for (const Seedling& sd : seedlings.seedlings()) {
    if (!sd.planted) continue;
    p.tilts_deg.push_back(sd.tilt_deg);
    p.peaks_N.push_back(sd.peak_force_N);
    xs.push_back(sd.x_m);
  }
  std::sort(xs.begin(), xs.end());
  for (std::size_t k = 1; k < xs.size(); ++k) p.spacing_mm.push_back((xs[k] - xs[k - 1]) * 1000);
  return p;
}

// The figures table: each figure rounded for a reader; green or red where it has a goal.
void figures_table(std::ostream& out, const Summary& s) {
  enum class Goal { none, met, missed };
  auto goal = [](bool met) { return met ? Goal::met : Goal::missed; };
  auto row = [&](const char* name, double v, int decimals, const char* unit, const char* against,
                 Goal g) {
    const char* colour = g == Goal::met      ? " style='color:#080'"
                         : g == Goal::missed ? " style='color:#c00'"
                                             : "";
    // The number, its unit and its mark on one line (no-break spaces).
    out << "<tr><td>" << name << "</td><td" << colour << "><b>" << report::fixed(v, decimals)
        << "</b>" << (*unit != '\0' ? "&nbsp;" : "") << unit
        << (g == Goal::met      ? "&nbsp;&#10003;"
            : g == Goal::missed ? "&nbsp;&#10007;"
                                : "")
        << "</td><td>" << against << "</td></tr>";
  };
  const double ceiling = s.clamp_ceiling_N;
  out << "<h2>Figures</h2><table>";
  row("uprightness", s.uprightness_pct, 2, "%",
      "paper: 94.8 % predicted, 93.86 % field (a comparison, not a target: the model's values "
      "and their sources are under Model assumptions)",
      Goal::none);
  row("seedlings lodged", s.seedlings_lodged, 0, "", "lying in the furrow (tilt 90 deg)",
      Goal::none);
  row("damage rate", s.damage_pct, 2, "%",
      "paper: 3 % predicted, 2.76 % field (a comparison, not a target)", Goal::none);
  row("seedlings fell from the clamp", s.seedlings_fell_in_carry, 0, "",
      "in the carry, too little grip for their weight and accelerations: skips", Goal::none);
  row("seedlings turned in the clamp", s.seedlings_turned_in_clamp, 0, "",
      "by more than 5 deg, the soil's moment beating the lips' friction", Goal::none);
  row("plant spacing, mean", s.spacing_mean_mm, 1, "mm", "agronomy: 20-30 mm",
      goal(s.spacing_mean_mm >= 20.0 && s.spacing_mean_mm <= 30.0));
  row("plant spacing, CV", s.spacing_cv_pct, 1, "%", "", Goal::none);
  row("seedlings planted", s.seedlings_planted, 0, "", "paper: 96-100 per 3 m plot", Goal::none);
  row("true sigma, mean", s.sigma_true_mean, 3, "", "target 1.5", Goal::none);
  row("true sigma, RMS error", s.sigma_true_rms_error_pct, 2, "%", "goal < 2 %",
      goal(s.sigma_true_rms_error_pct < 2.0));
  row("controller's sigma, RMS error", s.sigma_ctrl_rms_error_pct, 2, "%", "", Goal::none);
  row("clamp force, mean", s.clamp_force_mean_N, 1, "N", "paper: 90-92 N", Goal::none);
  row("clamp force, max", s.clamp_force_max_N, 1, "N", "must stay below the ceiling",
      goal(s.clamp_force_max_N < ceiling));
  row("clamp ceiling", ceiling, 1, "N",
      "derived from the stems' measured strength (Model assumptions)", Goal::none);
  row("depth, mean", s.depth_mean_mm, 1, "mm", "target 102 mm", Goal::none);
  row("depth, RMS error", s.depth_rms_error_mm, 2, "mm", "goal within 5 mm",
      goal(s.depth_rms_error_mm <= 5.0));
  row("CAN bus load", s.can_bus_load_pct, 1, "%", "", Goal::none);
  row("real-time factor", s.realtime_factor, 0, "x", "", Goal::none);
  out << "</table><p>Seedlings per 3 m plot: ";
  for (int c : s.plot_counts) out << c << ' ';
  out << "</p>";
}

// The machine's signals over time: ground speed, sigma, disc speed, clamp force, depth.
void signal_plots(std::ostream& out, report::ChartPage& charts, const Summary& s,
                  const ReportSeries& r) {
  const std::string t = "time [s]";
  const double ceiling = s.clamp_ceiling_N;
  out << "<h2>Plots</h2>"
      << charts.lines({"Ground speed", "m/s", t, 0, 0.1, {}, {}, ""}, r.t,
                      {{&r.v_ground, "#000", "true"}, {&r.v_wheel, "#d60", "soil wheel"}})
      << charts.lines({"Sigma = R omega / v",
                       "",
                       t,
                       1.2,
                       1.8,
                       {},
                       {{s.sigma_target, "#999", "target"}},
                       "Undefined below 0.02 m/s: a gap at the stops."},
                      r.t, {{&r.sigma_true, "#06c", "true"}, {&r.sigma_ctrl, "#d60", "controller"}})
      << charts.lines({"Disc speed", "rad/s", t, 0, 0.5, {}, {}, ""}, r.t,
                      {{&r.omega, "#06c", "measured"}, {&r.omega_cmd, "#d60", "command"}})
      << charts.lines({"Clamp force", "N", t, 0, 140, {}, {{ceiling, "#c00", "ceiling"}}, ""}, r.t,
                      {{&r.clamp_force, "#06c", "true"}, {&r.clamp_force_cmd, "#d60", "set-point"}})
      << charts.lines({"Furrow depth", "mm", t, 0, 170, {}, {}, ""}, r.t,
                      {{&r.depth, "#06c", "true"}, {&r.depth_cmd, "#d60", "command"}});
}

// The seedlings' outcomes: tilt, spacing against the planting monitor's own rule and ratios
// (as its figures and the summary count them), and the peak force in the nip.
void outcome_histograms(std::ostream& out, report::ChartPage& charts, const Scenario& sc,
                        const Summary& s, const Planted& p) {
  const PlantingMonitorConfig& monitor = sc.board.controller.monitor;
  const double spacing_target_mm = monitor.target_spacing_mm;
  int skips = 0, multiples = 0;
  for (const double g : p.spacing_mm) {
    if (monitor.is_skip(g)) ++skips;
    if (monitor.is_multiple(g)) ++multiples;
  }
  // The strength is the measured peaks' (or the scenario's), never the DEM's (issue 27).
  const double strength_N = sc.plant.seedlings.strength_mean();
  out << "<h2>Seedling outcomes</h2>"
      << charts.histogram({"Tilt after covering; lodged seedlings (+-90) in the end bins",
                           "",
                           "tilt from vertical, + top forward [deg]",
                           0,
                           0,
                           {{0.0, "#999", "upright"}},
                           {},
                           ""},
                          p.tilts_deg, -30, 30, 60)
      << charts.histogram(
             {"Spacing between planted seedlings",
              "",
              "spacing [mm]",
              0,
              0,
              {{monitor.multiple_ratio * spacing_target_mm, "#c00",
                "multiple (<= " + report::fixed(monitor.multiple_ratio, 1) + " x target)"},
               {spacing_target_mm, "#999", "target"},
               {monitor.skip_ratio * spacing_target_mm, "#c00",
                "skip (> " + report::fixed(monitor.skip_ratio, 1) + " x target)"}},
              {},
              std::to_string(skips) + " skips and " + std::to_string(multiples) +
                  " multiples against a target of " + report::fixed(spacing_target_mm, 1) + " mm."},
             p.spacing_mm, 0, 80, 80)
      << charts.histogram(
             {"Peak radial force in the roller nip",
              "",
              "force [N]",
              0,
              0,
              {{strength_N, "#c00", "mean strength"}, {s.clamp_ceiling_N, "#d60", "clamp ceiling"}},
              {},
              ""},
             p.peaks_N, 40, 200, 80);
}

}  // namespace

std::string report_html(const Scenario& sc, const Summary& s, const ReportSeries& r,
                        const SeedlingProcess& seedlings, const std::string& map_html) {
  std::ostringstream out;
  report::ChartPage charts;
  out << "<!doctype html><html><head>" << report::kReportHead
      << "<title>planter-sim: " << html_escape(s.scenario) << "</title>"
      << "<style>body{font-family:sans-serif;max-width:900px;margin:20px auto}td{padding:2px 10px}"
      << "table{border-collapse:collapse}tr:nth-child(even){background:#f4f4f4}</style>"
      << report::ChartPage::head() << "</head><body>"
      << "<h1>Simulated run: " << html_escape(s.scenario) << "</h1><p>Scenario <code>"
      << report::html_path(sc.file) << "</code>, board <code>" << html_escape(sc.board.name)
      << "</code>, seed " << sc.seed << ".</p>";
  figures_table(out, s);
  signal_plots(out, charts, s, r);
  outcome_histograms(out, charts, sc, s, planted_of(seedlings));
  if (!map_html.empty()) out << "<h2>The row as planted, by GNSS</h2>" << map_html;
  out << "<h2>Model assumptions</h2><p>Written from the configuration that ran.</p><ul>";
  for (const std::string& a : s.assumptions) out << "<li>" << html_escape(a) << "</li>";
  out << "</ul></body></html>";
  return out.str();
}

}  // namespace planter::sim
