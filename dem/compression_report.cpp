#include "dem/compression_report.h"

#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "config/durable_file.h"
#include "dem/dem_params.h"
#include "dem/result_json.h"
#include "report/chart.h"
#include "report/html_text.h"

namespace planter::dem {
namespace {

// The paper's figures the result is compared with.
constexpr double kPaperPeak_N = 140.6;
constexpr double kPaperPeakDisplacement_mm = 4.0;

}  // namespace

std::string compression_result_json(const CompressionRun& run) {
  const CompressionResult& r = run.result;
  nlohmann::json j;
  put_result_figures(j, r);
  j["peak_displacement_mm"] = r.peak_displacement_m * 1e3;
  j["platen_speed_m_min"] = run.setup.platen_speed_mps * 60.0 * run.setup.speedup;
  j["speedup"] = run.setup.speedup;
  j["wall_s"] = run.wall_s;
  j["particle_steps_per_s"] =
      run.wall_s > 0 ? static_cast<double>(r.particles) * static_cast<double>(r.steps) / run.wall_s
                     : 0.0;
  j["paper"] = {{"peak_force_N", kPaperPeak_N},
                {"peak_displacement_mm", kPaperPeakDisplacement_mm},
                {"peak_error_pct", 100.0 * (r.peak_force_N - kPaperPeak_N) / kPaperPeak_N}};
  return j.dump(2) + "\n";
}

void write_compression_outputs(config::OutputSet& out, const CompressionRun& run) {
  const CompressionResult& r = run.result;
  std::ostringstream csv;
  csv << "displacement_mm,force_N,broken_bonds\n";
  char line[96];
  for (const auto& p : r.curve) {
    std::snprintf(line, sizeof line, "%.5f,%.4f,%d\n", p.displacement_m * 1e3, p.force_N,
                  p.broken_bonds);
    csv << line;
  }
  out.write("curve.csv", csv.str());
  out.write("result.json", compression_result_json(run));
  out.write("params.toml", compression_setup_toml(run.setup));

  std::vector<double> x, f, broken;
  double f_max = 1.0, b_max = 1.0;
  for (const auto& p : r.curve) {
    x.push_back(p.displacement_m * 1e3);
    f.push_back(p.force_N);
    broken.push_back(p.broken_bonds);
    f_max = std::max(f_max, p.force_N);
    b_max = std::max(b_max, static_cast<double>(p.broken_bonds));
  }
  report::ChartPage charts;
  std::ostringstream html;
  html.precision(4);
  html << "<!doctype html><html><head>" << report::kReportHead
       << "<title>planter-dem compress</title>"
       << "<style>body{font-family:sans-serif;max-width:900px;margin:20px auto}td{padding:2px "
          "10px}</style>"
       << report::ChartPage::head()
       << "</head><body><h1>Radial compression of the seedling model</h1><table>"
       << "<tr><td>first peak</td><td><b>" << r.peak_force_N << " N</b> at "
       << r.peak_displacement_m * 1e3 << " mm"
       << (r.first_peak_found ? "" : " (no drop within the stroke: this is the maximum)")
       << "</td><td>paper: 140.6 N at about 4 mm; measured peaks 127.2-191.6 N</td></tr>"
       << "<tr><td>collapse (the largest fall)</td><td>" << collapse_text(r) << "</td><td>"
       << (r.collapse_drop_N <= 0.0 ? ""
           : r.collapse_force_N > 1.02 * r.peak_force_N
               ? "a later peak than the first: the first drop came before the tube's collapse"
               : "the first peak")
       << "</td></tr>"
       << "<tr><td>broken bonds</td><td>" << r.broken_bonds << " of " << r.bonds << "</td></tr>"
       << "<tr><td>particles</td><td>" << r.particles << "</td></tr>"
       << "<tr><td>platen speed</td><td>" << run.setup.platen_speed_mps * 60.0 * run.setup.speedup
       << " m/min (" << run.setup.speedup << "x the paper's 0.2 m/min)</td></tr>"
       << "<tr><td>quasi-static check</td><td>kinetic energy / platen work at most "
       << r.max_kinetic_to_work << "</td></tr>"
       << "<tr><td>steps</td><td>" << r.steps << " of " << run.setup.time_step_s << " s, in "
       << run.wall_s << " s</td></tr></table>"
       << charts.lines(
              {"Upper platen force",
               "N",
               "platen displacement [mm]",
               0.0,
               // The paper's peak always in view; a curve far above it zooms out.
               std::max(std::min(f_max, 4.0 * std::max(r.peak_force_N, 50.0)), 1.15 * kPaperPeak_N),
               {{kPaperPeakDisplacement_mm, "#36c", "paper's peak, about 4 mm"},
                {r.peak_displacement_m * 1e3, "#c33", "model's first peak"}},
               {{kPaperPeak_N, "#36c", "paper's 140.6 N"},
                {r.peak_force_N, "#c33", "model's first peak"}},
               ""},
              x, {{&f, "#c33", "DEM"}})
       << charts.lines({"Broken bonds", "", "platen displacement [mm]", 0.0, b_max, {}, {}, ""}, x,
                       {{&broken, "#555", "broken"}})
       << "<p>Curve: <code>curve.csv</code>; parameters: <code>params.toml</code>.</p>"
       << "</body></html>\n";
  out.write("report.html", html.str());
  out.commit();
}

}  // namespace planter::dem
