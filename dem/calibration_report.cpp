// What `planter-dem calibrate` writes: calibration.json (every design, response and ANOVA),
// calibrated.toml (the optimum as a --params file) and a self-contained report.html.
#include <cmath>
#include <nlohmann/json.hpp>
#include <sstream>

#include "config/durable_file.h"
#include "dem/calibration.h"
#include "dem/dem_params.h"
#include "doe/doe_report.h"
#include "report/chart.h"
#include "report/html_text.h"

namespace planter::dem {
namespace {

nlohmann::json runs_json(const std::vector<DesignRun>& runs) {
  nlohmann::json j = nlohmann::json::array();
  for (const auto& d : runs) {
    j.push_back({{"coded", d.coded},
                 {"peak_force_N", d.result.peak_force_N},
                 {"peak_displacement_mm", d.result.peak_displacement_m * 1e3},
                 {"first_peak_found", d.result.first_peak_found},
                 {"broken_bonds", d.result.broken_bonds}});
  }
  return j;
}

// calibration.json: every design, its responses and ANOVA, and the optimum where reached.
nlohmann::json calibration_json(const CalibrationOptions& o, const CalibrationReport& r) {
  nlohmann::json j;
  j["target_N"] = o.target_N;
  j["complete"] = r.complete;
  j["new_runs"] = r.new_runs;
  j["reused_runs"] = r.reused_runs;
  if (!r.refinement_stopped.empty()) j["refinement_stopped"] = r.refinement_stopped;
  for (const auto& f : r.factors) {
    j["factors"].push_back({{"name", f.name},
                            {"unit", f.unit},
                            {"low", f.low},
                            {"high", f.high},
                            {"log_scale", f.log_scale}});
  }
  j["plackett_burman"] = {{"runs", runs_json(r.screening)},
                          {"anova", doe::anova_json(r.screening_anova)}};
  nlohmann::json chosen = nlohmann::json::array();
  for (int k : r.chosen) chosen.push_back(r.factors[static_cast<std::size_t>(k)].name);
  j["chosen"] = {{"factors", chosen}, {"reason", r.chosen_reason}};
  j["steepest_ascent"] = {{"runs", runs_json(r.ascent)}, {"best_step", r.best_step}};
  j["box_behnken"] = {{"low", r.bb_low},
                      {"centre", r.bb_centre},
                      {"high", r.bb_high},
                      {"runs", runs_json(r.box_behnken)},
                      {"anova", doe::anova_json(r.surface)}};
  if (!r.complete) return j;
  const double got = r.verification.result.peak_force_N;
  j["optimum"] = {
      {"coded", {r.optimum_coded(0), r.optimum_coded(1), r.optimum_coded(2)}},
      {"predicted_N", r.predicted_N},
      {"verified_peak_N", got},
      {"verified_peak_displacement_mm", r.verification.result.peak_displacement_m * 1e3},
      {"verified_collapse_force_N", r.verification.result.collapse_force_N},
      {"error_pct", 100.0 * (got - o.target_N) / o.target_N}};
  const auto& c = r.calibrated;
  j["calibrated"] = {{"normal_stiffness_N_m3", c.setup.bonds.normal_stiffness_N_m3},
                     {"tensile_strength_Pa", c.setup.bonds.tensile_strength_Pa},
                     {"peak_force_N", c.result.peak_force_N},
                     {"peak_displacement_mm", c.result.peak_displacement_m * 1e3},
                     {"collapse_force_N", c.result.collapse_force_N},
                     {"collapse_displacement_mm", c.result.collapse_displacement_m * 1e3},
                     {"refinement_runs", r.refinement.size()},
                     {"error_pct", 100.0 * (c.result.peak_force_N - o.target_N) / o.target_N}};
  return j;
}

// The report's design sections: the screening with its factors named, and the path.
void design_sections(std::ostream& h, const CalibrationReport& r) {
  h << "<h2>Plackett-Burman screening (12 runs, main effects)</h2>"
    << doe::anova_table_html(r.screening_anova);
  // The table's terms are the factors' codes: what each one is, and the range it spanned.
  h << "<p>The factors:</p><ul>";
  for (const Factor& f : screening_factors()) {
    const std::size_t space = f.name.find(' ');
    h << "<li><b>" << report::html_escape(f.name.substr(0, space)) << "</b> "
      << report::html_escape(space == std::string::npos ? "" : f.name.substr(space + 1)) << ", "
      << f.low << " to " << f.high << " " << report::html_escape(f.unit) << "</li>";
  }
  h << "</ul><p>" << r.chosen_reason << ".</p>";
  h << "<h2>Steepest ascent</h2><table><tr><th>step</th><th>peak [N]</th><th>at [mm]</th></tr>";
  for (std::size_t s = 0; s < r.ascent.size(); ++s) {
    h << "<tr><td>" << s << (static_cast<int>(s) == r.best_step ? " (best)" : "") << "</td><td>"
      << r.ascent[s].result.peak_force_N << "</td><td>"
      << r.ascent[s].result.peak_displacement_m * 1e3 << "</td></tr>";
  }
  h << "</table>";
  if (!r.box_behnken.empty() && r.surface.beta.size() > 0) {
    h << "<h2>Box-Behnken (13 runs) and the quadratic surface</h2>"
      << doe::anova_table_html(r.surface);
  }
}

// The report's result: the optimum's check run, the refinement, and the calibrated curve with
// its first peak and collapse marked.
void result_sections(std::ostream& h, report::ChartPage& charts, const CalibrationOptions& o,
                     const CalibrationReport& r) {
  const auto& v = r.verification;
  h << "<h2>Optimum</h2><p>Predicted " << r.predicted_N << " N; the run there gives <b>"
    << v.result.peak_force_N << " N at " << v.result.peak_displacement_m * 1e3 << " mm</b> ("
    << 100.0 * (v.result.peak_force_N - o.target_N) / o.target_N << " %).</p>";
  const auto& c = r.calibrated;
  h << "<h2>Refinement</h2><p>" << r.refinement.size()
    << " run(s) scaling S and sigma_c together (force) and their ratio (peak position). "
    << "Calibrated: S = " << c.setup.bonds.normal_stiffness_N_m3
    << " N/m<sup>3</sup>, sigma_c = " << c.setup.bonds.tensile_strength_Pa << " Pa: <b>"
    << c.result.peak_force_N << " N at " << c.result.peak_displacement_m * 1e3
    << " mm</b> (first peak: the first 5 % drop); collapse (the largest fall) "
    << collapse_text(c.result)
    << ". Both are marked on the chart. Parameters: <code>calibrated.toml</code>.</p>";
  std::vector<double> x, f;
  for (const auto& p : r.calibrated.result.curve) {
    x.push_back(p.displacement_m * 1e3);
    f.push_back(p.force_N);
  }
  std::vector<report::Marker> at_x{{c.result.peak_displacement_m * 1e3, "#c33", "first peak"}};
  std::vector<report::Marker> at_y{{o.target_N, "#36c", "target"},
                                   {c.result.peak_force_N, "#c33", "first peak"}};
  if (c.result.collapse_drop_N > 0.0) {  // a curve that never falls has no collapse to mark
    at_x.push_back({c.result.collapse_displacement_m * 1e3, "#933", "collapse"});
    at_y.push_back({c.result.collapse_force_N, "#933", "collapse"});
  }
  h << charts.lines({"Calibrated model: upper platen force", "N", "displacement [mm]", 0.0,
                     std::max(1.15 * c.result.collapse_force_N,
                              std::max(1.15 * c.result.peak_force_N, 1.15 * o.target_N)),
                     at_x, at_y, ""},
                    x, {{&f, "#c33", "DEM, calibrated"}});
}

}  // namespace

void write_calibration_outputs(const CalibrationOptions& o, const CalibrationReport& r) {
  if (r.complete)
    config::write_output_file(o.out_dir + "/calibrated.toml",
                              compression_setup_toml(r.calibrated.setup));
  config::write_output_file(o.out_dir + "/calibration.json", calibration_json(o, r).dump(2) + "\n");

  std::ostringstream h;
  h.precision(4);
  report::ChartPage charts;
  h << "<!doctype html><html><head>" << report::kReportHead
    << "<title>planter-dem calibrate</title>"
    << "<style>body{font-family:sans-serif;max-width:900px;margin:20px auto}td,th{padding:2px "
       "8px}table{border-collapse:collapse}tr:nth-child(even){background:#f4f4f4}</style>"
    << report::ChartPage::head() << "</head><body><h1>Calibration of the seedling model to "
    << o.target_N << " N</h1>";
  if (!r.complete) h << "<p><b>Incomplete</b>: run again with the same --out to resume.</p>";
  design_sections(h, r);
  if (r.complete) result_sections(h, charts, o, r);
  h << "</body></html>\n";
  config::write_output_file(o.out_dir + "/report.html", h.str());
}

}  // namespace planter::dem
