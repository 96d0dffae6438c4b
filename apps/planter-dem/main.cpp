// planter-dem: the seedling's bonded-particle model.
//   compress   the paper's radial compression test: curve, first peak, report
//   calibrate  Plackett-Burman, steepest ascent, Box-Behnken + ANOVA to a target peak force
//   reduce     the reduced-order force model F(delta, delta_dot) for the plant model
//   plan-run   one run of a calibration stage's plan (what a Slurm task executes)
// Exit codes: 0 done, 1 the run failed (an output could not be written), 2 bad input.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "apps/version/cli_errors.h"
#include "apps/version/executor_options.h"
#include "apps/version/list_keys.h"
#include "apps/version/version.h"
#include "config/cli_range.h"
#include "config/config_error.h"
#include "config/durable_file.h"
#include "dem/calibration.h"
#include "dem/calibration_runs.h"
#include "dem/compression_report.h"
#include "dem/dem_keys.h"
#include "dem/dem_params.h"
#include "dem/reduced_order.h"

namespace {

using namespace planter;

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "planter-dem: %s\n", message.c_str());
  return code;
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

struct Common {
  std::string params;
  std::string out;
  bool force = false;
  long max_steps = 2'000'000;  // 100x the defaults' 18000: minutes, not hours
  // Particles x steps: the work, and with the particles the memory (about 1.6 kB a particle
  // with its bonds and contacts). 100x the defaults' (693 x 18000): minutes, not hours.
  double max_particle_steps = 1.25e9;
  double speedup = 0.0;
  double diameter_mm = 0.0;
};

dem::CompressionSetup load_setup(const Common& c) {
  dem::CompressionSetup s =
      c.params.empty() ? dem::CompressionSetup{} : dem::load_compression_setup(c.params);
  if (c.speedup > 0.0) s.speedup = c.speedup;
  if (c.diameter_mm > 0.0) s.seedling.diameter_m = c.diameter_mm * 1e-3;
  // The cost before the run: a 1e-8 s step or speedup 1 is hours of work per compression.
  const long steps = dem::compression_steps(s);
  if (steps > c.max_steps) {
    throw config::ConfigError(
        c.params.empty() ? "planter-dem" : c.params, 0, "",
        "one compression would take " + std::to_string(steps) + " steps (time_step_s " +
            std::to_string(s.time_step_s) + ", speedup " + std::to_string(s.speedup) +
            "; the defaults take " + std::to_string(dem::compression_steps({})) +
            "); raise time_step_s or --speedup, or allow it with --max-steps");
  }
  const long particles = dem::seedling_particle_count(s.seedling);
  const double work = static_cast<double>(particles) * static_cast<double>(steps);
  if (work > c.max_particle_steps) {
    char what[400];
    std::snprintf(what, sizeof what,
                  "one compression would take %ld particles x %ld steps = %.3g particle-steps "
                  "(the defaults: %ld x %ld); coarser particles, a shorter seedling, a larger "
                  "time_step_s or --speedup, or allow it with --max-particle-steps",
                  particles, steps, work, dem::seedling_particle_count({}),
                  dem::compression_steps({}));
    throw config::ConfigError(c.params.empty() ? "planter-dem" : c.params, 0, "", what);
  }
  return s;
}

int compress(const Common& c, int threads) {
  dem::CompressionRun run;
  run.setup = load_setup(c);
  config::OutputSet out(c.out, "planter-dem compress", c.force);
  // Said before the run (seconds of silence otherwise), and which seedling it is: with no
  // --params these are the paper's published values, not the calibrated seedling (issue 54).
  if (c.params.empty())
    std::printf(
        "parameters: the paper's, as published (no --params); the calibrated seedling is "
        "models/seedling_dem.toml (--params)\n");
  else
    std::printf("parameters: %s\n", c.params.c_str());
  std::printf("compressing: %ld steps...\n", dem::compression_steps(run.setup));
  std::fflush(stdout);
  const auto t0 = std::chrono::steady_clock::now();
  // On a terminal, the platen's travel as it goes (a compression runs for seconds).
  std::function<void(const dem::CurvePoint&)> on_sample;
  std::size_t samples = 0;
  if (isatty(STDOUT_FILENO))
    on_sample = [&](const dem::CurvePoint& p) {
      if (++samples % 10 != 0) return;
      std::printf("\rcompressing: %.2f of %.2f mm, %.1f N, %d bonds broken\x1b[K",
                  p.displacement_m * 1e3, run.setup.stroke_m * 1e3, p.force_N, p.broken_bonds);
      std::fflush(stdout);
    };
  run.result = dem::run_compression(run.setup, threads, on_sample);
  if (on_sample) std::printf("\r\x1b[K");
  run.wall_s = seconds_since(t0);
  dem::write_compression_outputs(out, run);
  const auto& r = run.result;
  std::printf("seedling: %d particles, %d bonds; %ld steps of %g s; platen %g m/min (%gx)\n",
              r.particles, r.bonds, r.steps, run.setup.time_step_s,
              run.setup.platen_speed_mps * 60.0 * run.setup.speedup, run.setup.speedup);
  std::printf("quasi-static check: kinetic energy / platen work <= %.4f\n", r.max_kinetic_to_work);
  std::printf("broken bonds: %d of %d\n", r.broken_bonds, r.bonds);
  std::printf("outputs: %s/{curve.csv,result.json,params.toml,report.html}\n", c.out.c_str());
  std::printf("collapse (the largest fall): %s\n", dem::collapse_text(r).c_str());
  std::printf("%s: %.1f N at %.2f mm (paper: 140.6 N at about 4 mm), %.1f s wall\n",
              r.first_peak_found ? "first peak" : "maximum (no peak within the stroke)",
              r.peak_force_N, r.peak_displacement_m * 1e3, run.wall_s);
  return 0;
}

int calibrate(const Common& c, double target_N, double target_mm, int jobs, int max_new_runs,
              const plan::ExecutorOptions& executor) {
  if (const std::string why = plan::executor_refusal(executor); !why.empty()) return fail(2, why);
  dem::CalibrationOptions o;
  o.executor = executor;
  o.base = load_setup(c);
  o.target_N = target_N;
  o.target_displacement_mm = target_mm;
  o.jobs = jobs;
  o.max_new_runs = max_new_runs;
  o.out_dir = c.out;
  const auto t0 = std::chrono::steady_clock::now();
  dem::CalibrationReport r;
  try {
    r = dem::calibrate(
        o, [](const std::string& line) { std::fprintf(stderr, "  %s\n", line.c_str()); });
  } catch (const plan::PlanWritten& w) {
    std::printf(
        "plan written in %s (the first stage's runs; the next stages' runs follow from "
        "their results); run it: %s, then this command again\n",
        w.dir.c_str(), w.how_to_run.c_str());
    return 0;
  }
  dem::write_calibration_outputs(o, r);
  std::printf("runs: %d new, %d reused from %s/runs, %d jobs, %.1f s wall\n", r.new_runs,
              r.reused_runs, c.out.c_str(), jobs, seconds_since(t0));
  if (!r.complete) {
    std::printf("stopped before the end (--max-new-runs); run again with --out %s to resume\n",
                c.out.c_str());
    return 3;
  }
  std::printf("screening: %s\n", r.chosen_reason.c_str());
  for (const auto& t : r.screening_anova.terms)
    std::printf("  %-3s effect %+9.2f N  p = %.4f\n", t.name.c_str(), 2.0 * t.coefficient,
                t.p_value);
  std::printf("steepest ascent: best step %d\n", r.best_step);
  std::printf(
      "box-behnken surface: p = %.3g, R2 = %.4f, adjusted R2 = %.4f, adequate "
      "precision %.1f\n",
      r.surface.model_p, r.surface.r2, r.surface.r2_adjusted, r.surface.adequate_precision);
  for (std::size_t m = 0; m < r.chosen.size(); ++m) {
    const auto& f = r.factors[static_cast<std::size_t>(r.chosen[m])];
    std::printf("  %s: %.4g .. %.4g .. %.4g %s\n", f.name.c_str(), r.bb_low[m], r.bb_centre[m],
                r.bb_high[m], f.unit.c_str());
  }
  std::printf("outputs: %s/{calibration.json,calibrated.toml,report.html}\n", c.out.c_str());
  const auto& v = r.verification.result;
  std::printf(
      "box-behnken optimum: predicted %.1f N; simulated %.1f N at %.2f mm (%+.1f %%); collapse "
      "%s\n",
      r.predicted_N, v.peak_force_N, v.peak_displacement_m * 1e3,
      100.0 * (v.peak_force_N - target_N) / target_N, dem::collapse_text(v).c_str());
  if (!r.refinement_stopped.empty())
    std::printf("refinement stopped: %s\n", r.refinement_stopped.c_str());
  const auto& cal = r.calibrated;
  std::printf("refined in %zu run(s): S = %.4g N/m^3, sigma_c = %.4g Pa\n", r.refinement.size(),
              cal.setup.bonds.normal_stiffness_N_m3, cal.setup.bonds.tensile_strength_Pa);
  std::printf("calibrated: collapse (the largest fall) %s\n",
              dem::collapse_text(cal.result).c_str());
  std::printf(
      "calibrated: first peak (a 5 %% drop) %.1f N at %.2f mm (target %.1f N%s, %+.1f %%)\n",
      cal.result.peak_force_N, cal.result.peak_displacement_m * 1e3, target_N,
      o.target_displacement_mm > 0
          ? (" at " + std::to_string(o.target_displacement_mm).substr(0, 4) + " mm").c_str()
          : "",
      100.0 * (cal.result.peak_force_N - target_N) / target_N);
  return 0;
}

int reduce(const Common& c, const std::vector<double>& diameters_mm, int jobs) {
  const dem::CompressionSetup base = load_setup(c);
  config::OutputSet out(c.out, "planter-dem reduce", c.force);
  const auto t0 = std::chrono::steady_clock::now();
  // Progress on a terminal only: logs and pipes get the summary alone.
  std::function<void(std::size_t, std::size_t)> progress;
  if (isatty(STDERR_FILENO))
    progress = [](std::size_t done, std::size_t total) {
      std::fprintf(stderr, "\rplanter-dem reduce: %zu of %zu compressions done\x1b[K%s", done,
                   total, done == total ? "\n" : "");
    };
  const std::string source =
      "from " + (c.params.empty() ? std::string("the paper's parameters") : c.params);
  // The first line at once, not after the first compression (6 s; issue 54).
  if (progress) {
    std::fprintf(stderr, "planter-dem reduce: the seedling %s, %zu diameters: compressing...\n",
                 source.c_str(), diameters_mm.size());
  }
  const dem::ReducedOrderFit fit = dem::fit_reduced_order(base, diameters_mm, jobs, progress);
  const std::string path = c.out + "/seedling_force.toml";
  out.write("seedling_force.toml", dem::reduced_order_toml(fit, source));
  out.commit();
  std::printf("diameter   peak force   at      elastic fit rms\n");
  for (const auto& dc : fit.curves) {
    std::printf("%6.2f mm  %8.1f N  %5.2f mm  %6.2f N%s\n", dc.diameter_mm, dc.result.peak_force_N,
                dc.result.peak_displacement_m * 1e3, dc.fit_rms_N,
                dc.result.first_peak_found ? "" : "  (no peak within the stroke)");
  }
  const auto& m = fit.model;
  std::printf(
      "F = %.4g (1 %+.3g (d - %.4g)) delta^%.3f + %.3g delta_dot; peak %.1f N %+.1f N/mm at "
      "%.2f mm; collapse to %.0f %%\n",
      m.stiffness_N_per_mm_n, m.stiffness_slope_per_mm / m.stiffness_N_per_mm_n,
      m.reference_diameter_mm, m.exponent, m.damping_N_s_per_mm, m.peak_force_N,
      m.peak_force_slope_N_per_mm, m.peak_displacement_mm, 100.0 * m.residual_fraction);
  std::printf("model: %s (%.1f s wall)\n", path.c_str(), seconds_since(t0));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "planter-dem: the seedling's bonded-particle model, its calibration and the "
      "reduced-order force model"};
  app.set_version_flag("--version", std::string("planter-dem ") + planter::apps::version());
  planter::apps::add_list_keys_flag(app, planter::dem::kDemFileKeys, "the --params file");
  app.require_subcommand(1);
  Common common;
  auto add_common = [&](CLI::App* sub) {
    sub->add_option("--params", common.params, "parameter file (TOML); default: the paper's")
        ->check(CLI::ExistingFile);
    sub->add_option("--out", common.out, "output directory")->required();
    sub->add_flag("--force", common.force,
                  "replace --out even if it holds something other than this command's output");
    sub->add_option("--max-steps", common.max_steps,
                    "refuse a compression longer than this many time steps")
        ->capture_default_str()
        ->check(planter::config::finite_range(1L, 1'000'000'000'000L));
    sub->add_option("--max-particle-steps", common.max_particle_steps,
                    "refuse a compression of more particles x time steps than this")
        ->capture_default_str()
        ->check(planter::config::finite_range(1.0, 1e15));
    sub->add_option("--speedup", common.speedup, "platen speed over the paper's 0.2 m/min")
        ->check(planter::config::finite_range(1.0, 500.0));
    sub->add_option("--diameter-mm", common.diameter_mm, "seedling diameter")
        ->check(planter::config::finite_range(3.0, 30.0));
  };
  auto* compress_cmd = app.add_subcommand("compress", "the radial compression test");
  add_common(compress_cmd);
  int threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  compress_cmd
      ->add_option(
          "--threads", threads,
          "threads sharing each step (default: all cores; the same result on any number; 1 on a "
          "busy machine)")
      ->check(planter::config::finite_range(1, 256));
  auto* calibrate_cmd = app.add_subcommand("calibrate", "calibrate to a target peak force");
  add_common(calibrate_cmd);
  double target_N = 140.6;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  int max_new_runs = -1;
  double target_mm = 0.0;
  calibrate_cmd
      ->add_option("--target-displacement-mm", target_mm,
                   "also place the first peak here (refinement); 0 = force only")
      ->check(planter::config::finite_range(0.0, 20.0));
  calibrate_cmd->add_option("--target", target_N, "target first-peak force, N")
      ->check(planter::config::finite_range(1.0, 10000.0));
  calibrate_cmd->add_option("--jobs", jobs, "simulations at once (default: all cores)")
      ->check(planter::config::finite_range(1, 256));
  calibrate_cmd
      ->add_option("--max-new-runs", max_new_runs,
                   "stop after this many new simulations (resume later)")
      ->check(planter::config::finite_range(0, 100000));
  plan::ExecutorOptions executor;
  planter::apps::add_executor_options(*calibrate_cmd, executor);
  std::string plan_path;
  std::size_t plan_index = 0;
  auto* plan_run = app.add_subcommand(
      "plan-run", "run one run of a calibration stage's plan (what each Slurm task executes)");
  plan_run->add_option("plan", plan_path, "DIR/plans/STAGE/plan.json")->required();
  plan_run->add_option("index", plan_index, "the run's index in the plan")
      ->required()
      ->check(planter::config::whole_number());
  auto* reduce_cmd = app.add_subcommand("reduce", "fit the reduced-order force model");
  add_common(reduce_cmd);
  std::vector<double> diameters_mm{8.3, 9.3, 10.35, 11.4};
  reduce_cmd->add_option("--diameters-mm", diameters_mm, "seedling diameters to simulate")
      ->delimiter(',')
      ->check(planter::config::finite_range(3.0, 30.0));
  reduce_cmd->add_option("--jobs", jobs, "simulations at once (default: all cores)")
      ->check(planter::config::finite_range(1, 256));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return planter::apps::parse_ended(app, e, "planter-dem", argc, argv, 2);
  }
  try {
    if (*compress_cmd) return compress(common, threads);
    if (*reduce_cmd) return reduce(common, diameters_mm, jobs);
    if (*plan_run) {
      dem::execute_stage_run(plan_path, plan_index);
      return 0;
    }
    return calibrate(common, target_N, target_mm, jobs, max_new_runs, executor);
  } catch (const config::ConfigError& e) {
    return fail(2, e.what());
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
}
