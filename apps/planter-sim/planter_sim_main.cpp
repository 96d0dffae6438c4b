// planter-sim: runs a scenario in lockstep and writes recording.csv, summary.json, report.html;
// `devices` runs the plant in real time on a real CAN bus and gpio-sim for host-in-the-loop.
#include <CLI/CLI.hpp>
#include <atomic>
#include <bit>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>

#include "apps/planter-sim/as_planted.h"
#include "apps/planter-sim/replay.h"
#include "config/cli_range.h"
#include "config/config_error.h"
#include "config/nmea.h"
#include "config/output_set.h"
#include "config/recording_format.h"
#include "hal/linux/hal_error.h"
#ifdef PLANTER_WITH_CONSOLE
#include "apps/planter-sim/live.h"
#endif
#include "apps/planter-sim/monte_carlo.h"
#include "apps/planter-sim/robustness.h"
#include "apps/planter-sim/sensitivity.h"
#include "apps/planter-sim/sweep.h"
#include "sim/hil/realtime_devices.h"
#ifdef PLANTER_WITH_REPLAY
#include "analysis/recording.h"
#endif
#include "apps/version/cli_errors.h"
#include "apps/version/executor_options.h"
#include "apps/version/list_keys.h"
#include "apps/version/version.h"
#include "config/stem_strength.h"
#include "sim/plant/effect_keys.h"
#include "sim/plant/model_values.h"
#include "sim/runner/lockstep_runner.h"
#include "sim/runner/model_assumptions.h"
#include "sim/runner/recording_thread.h"
#include "sim/runner/recording_writer.h"
#include "sim/runner/run_plan.h"
#include "sim/runner/scenario_keys.h"

namespace fs = std::filesystem;
using namespace planter;
using namespace planter::sim;

namespace {

#ifdef PLANTER_WITH_SWEEP
// A study over many runs of one scenario (sensitivity, montecarlo, robustness): its options,
// with the scenario and the output folder, held for the subcommand's run.
template <class Options>
struct Study {
  std::string scenario, out = "out";
  Options options;
  CLI::App* cmd = nullptr;
};

// The options every study shares, on a new subcommand.
template <class Options>
std::shared_ptr<Study<Options>> add_study(CLI::App& app, const std::string& name,
                                          const std::string& description) {
  auto o = std::make_shared<Study<Options>>();
  Options& so = o->options;
  auto* cmd = app.add_subcommand(name, description);
  cmd->add_option("scenario", o->scenario, "base scenario file (TOML)")->required();
  cmd->add_option("--out", o->out, "output directory")->capture_default_str();
  cmd->add_flag("--force", so.force,
                "replace --out even if it holds something other than an analysis");
  cmd->add_option("--distance", so.distance_m, "metres per run")
      ->capture_default_str()
      ->check(planter::config::finite_range(0.5, 1000.0));
  cmd->add_option("--jobs", so.jobs, "runs at a time (0: one per core)")
      ->capture_default_str()
      ->check(planter::config::finite_range(0, 256));
  planter::apps::add_executor_options(*cmd, so.executor);
  o->cmd = cmd;
  return o;
}
#endif

void print_summary(const Summary& s) {
  std::printf("scenario            %s\n", s.scenario.c_str());
  if (s.board_is_hardware)
    std::printf(
        "board               %s: a machine's board; its settings run here, its bus and "
        "lines are not used\n",
        s.board.c_str());
  else
    std::printf("board               %s\n", s.board.c_str());
  std::printf("distance            %.2f m in %.1f s simulated (%.2f s wall, %.0fx real time)\n",
              s.distance_m, s.sim_seconds, s.wall_seconds, s.realtime_factor);
  std::printf("seedlings planted   %d  (per 3 m plot:", s.seedlings_planted);
  for (int c : s.plot_counts) std::printf(" %d", c);
  std::printf(")\n");
  std::printf("uprightness         %.2f %%, %d lodged   (paper: 94.8 predicted, 93.86 field)\n",
              s.uprightness_pct, s.seedlings_lodged);
  std::printf("damage rate         %.2f %%   (paper: 3 predicted, 2.76 field)\n", s.damage_pct);
  std::printf("damage seen         %.0f by the clamp's reading (truth: %d damaged)\n",
              s.monitor.damage_seen, s.seedlings_damaged);
  if (s.seedlings_damaged > 0)
    std::printf(
        "damaged seedlings   mean strength %.1f N, %d below the weakest measured (%.1f N)\n",
        s.damaged_strength_mean_N, s.damaged_below_measured, config::measured_strength().min_N);
  std::printf(
      "in the clamp        %d fell in the carry (skips), %d slid > 5 mm, %d turned > 5 deg\n",
      s.seedlings_fell_in_carry, s.seedlings_slid_in_clamp, s.seedlings_turned_in_clamp);
  std::printf("plant spacing       %.1f mm mean, CV %.1f %%   (agronomy: 20-30 mm)\n",
              s.spacing_mean_mm, s.spacing_cv_pct);
  if (s.monitor_fitted) {
    const PlantingFigures& m = s.monitor;
    std::printf(
        "planting monitor    %.0f seen, spacing %.1f mm CV %.3f, singulation %.2f %% (%.0f skips, "
        "%.0f multiples)%s\n",
        m.seedlings, m.spacing_mean_mm, m.spacing_cv, m.singulation_pct, m.skips, m.multiples,
        (s.warnings_seen & warning::kEmptyBelt) != 0 ? ", empty belt warned" : "");
    std::printf("                    truth: %d planted, %d skips, %d multiples\n",
                s.seedlings_planted, s.truth_skips, s.truth_multiples);
  } else {
    std::printf("planting monitor    none: the board has no seedling photo-eye\n");
  }
  // The alarms the operator was shown during the run (firmware/supervisor/loop_alarms.h).
  std::string alarms;
  for (int bit = 0; bit < warning::kCount; ++bit)
    if ((s.warnings_seen >> bit) & 1u)
      alarms += (alarms.empty() ? "" : "; ") + std::string(warning::name(bit));
  std::printf("alarms              %s\n", alarms.empty() ? "none" : alarms.c_str());
  std::printf("sigma (true)        mean %.4f, RMS error %.2f %%   (controller's view: %.2f %%)\n",
              s.sigma_true_mean, s.sigma_true_rms_error_pct, s.sigma_ctrl_rms_error_pct);
  std::printf("clamp force         mean %.1f N, max %.1f N, ceiling %.1f N\n", s.clamp_force_mean_N,
              s.clamp_force_max_N, s.clamp_ceiling_N);
  std::printf("furrow depth        mean %.1f mm, RMS error %.2f mm (target %.1f)\n",
              s.depth_mean_mm, s.depth_rms_error_mm, s.depth_target_mm);
  std::printf("CAN bus             %llu frames, load %.1f %%\n",
              static_cast<unsigned long long>(s.can_frames), s.can_bus_load_pct);
  std::printf("final state         %s (faults 0x%x", s.final_state.c_str(), s.faults);
  for (int bit = 0; bit < fault::kCount; ++bit) {
    if ((s.faults >> bit) & 1u)
      std::printf("%s%s", bit == std::countr_zero(s.faults) ? ": " : ", ", fault::name(bit));
  }
  std::printf(")\n");
}

// `places` (one per released seedling) adds lat_deg and lon_deg, empty where no fix placed it.
std::string seedlings_csv(const SeedlingProcess& process,
                          const std::vector<PlantedPlace>* places = nullptr) {
  std::ostringstream csv;
  // tilt_deg: + top forward, 90 lodged; sigma_at_release empty when released standing.
  // fell_in_carry 1: dropped from the clamp before the soil (a skip; no position or tilt).
  csv << "x_m,release_t,diameter_mm,length_mm,strength_N,peak_force_N,damaged,tilt_deg,sigma_"
         "at_release,burial_mm,clamp_turn_deg,lip_drag_deg,lodged,clamp_slip_mm,fall_deg,"
         "fell_in_carry"
      << (places ? ",lat_deg,lon_deg\n" : "\n");
  for (std::size_t i = 0; i < process.released(); ++i) {
    const Seedling& s = process.seedlings()[i];
    csv << s.x_m << ',' << s.release_time_s << ',' << s.diameter_mm << ',' << s.length_mm << ','
        << s.strength_N << ',' << s.peak_force_N << ',' << (s.damaged ? 1 : 0) << ',' << s.tilt_deg
        << ',';
    if (std::isfinite(s.sigma_at_release)) csv << s.sigma_at_release;
    csv << ',' << s.release.burial_mm << ',' << s.release.clamp_turn_deg << ','
        << s.release.lip_drag_deg << ',' << (s.release.lodged ? 1 : 0) << ','
        << s.release.clamp_slip_mm << ',' << s.release.fall_deg << ','
        << (s.release.fell_in_carry ? 1 : 0);
    if (places) {
      const PlantedPlace& p = (*places)[i];
      char ll[64] = ",,";
      if (p.known) std::snprintf(ll, sizeof ll, ",%.8f,%.8f", p.lat_deg, p.lon_deg);
      csv << ll;
    }
    csv << '\n';
  }
  return csv.str();
}

// The simulated receiver's fixes as NMEA (RMC, GGA), for gpsfake and other NMEA tools. The run
// starts at an assumed 2026-05-01 08:00:00 UTC: the times are the run's, the date any.
std::string gnss_nmea(const std::vector<hal::GnssFix>& fixes) {
  constexpr double kRunStartUtcS = 1777622400.0;
  std::string out;
  for (const hal::GnssFix& f : fixes)
    out += config::nmea_sentences(f, kRunStartUtcS + static_cast<double>(f.valid_ns) * 1e-9);
  return out;
}

// The scenario (with another board if one is given), its board's warnings printed once: every
// subcommand runs a board, so every one says what is in range but doubtful about it.
Scenario load_scenario_warned(const std::string& scenario_path, const std::string& board_path) {
  Scenario scenario = load_scenario(scenario_path);
  if (!board_path.empty()) scenario.board = config::load_board(board_path);
  for (const auto& w : scenario.board.warnings)
    std::fprintf(stderr, "planter-sim: warning: %s\n", w.c_str());
  return scenario;
}

int run_scenario(const std::string& scenario_path, const std::string& out_dir, bool quiet,
                 bool force) {
  const Scenario scenario = load_scenario_warned(scenario_path, "");
  config::OutputSet out(out_dir, "planter-sim run", force);
  LockstepRunner runner(scenario);
  RecordingWriter recording(
      out.path("recording.csv"), out.shown("recording.csv"),
      {{"source", "planter-sim"},
       {"scenario", scenario.name},
       {"board", scenario.board.name},
       {"seed", std::to_string(scenario.seed)},
       {"units", "1"},
       {std::string(config::kSyncPeriodKey),
        config::sync_period_value(scenario.board.controller.can.sync_period_ns)}});
  ReportSeries series;
  std::uint64_t tick = 0;
  RecordingThread recording_thread(recording);
  runner.set_observer([&](const TickRecord& row) {
    recording_thread.write(row);
    if (tick++ % 10 == 0) series.add(row);
  });
  Summary summary = runner.run();
  summary.assumptions = model_assumptions(scenario);
  recording_thread.close();
  out.write("summary.json", summary.to_json() + "\n");
  const bool gnss = scenario.board.controller.ground.gnss_fitted;
  const SeedlingProcess& planted = runner.plant().seedlings();
  std::vector<PlantedPlace> places;
  std::string map;
  if (gnss) {
    const PlantingMonitorConfig& monitor = scenario.board.controller.monitor;
    places = place_seedlings(planted, runner.gnss_fixes(), scenario.board.gnss);
    out.write("gnss.nmea", gnss_nmea(runner.gnss_fixes()));
    out.write("as_planted.geojson",
              as_planted_geojson(planted, places, runner.gnss_fixes(), monitor));
    map = as_planted_svg(planted, places, monitor);
  }
  out.write("seedlings.csv", seedlings_csv(planted, gnss ? &places : nullptr));
  out.write("report.html", report_html(scenario, summary, series, planted, map));
  out.commit();
  if (!quiet) print_summary(summary);
  for (const auto& note : summary.notes) std::printf("note: %s\n", note.c_str());
  std::printf("wrote %s/{recording.csv,seedlings.csv,summary.json,report.html%s}\n",
              out_dir.c_str(), gnss ? ",gnss.nmea,as_planted.geojson" : "");
  // A machine that never moved, with no fault the scenario scripted, is a broken board or
  // machine file, not a result (issue 28, item 12: an hour of a boot fault exited 0).
  const FaultEvents& scripted = scenario.faults;
  if (summary.distance_m <= 0.0 && scripted.estop_at_s < 0.0 && scripted.silent_node.empty()) {
    std::fprintf(stderr,
                 "planter-sim: the machine never moved: final state %s, faults 0x%X (the "
                 "controller did not reach running; recording.csv shows its boot)\n",
                 summary.final_state.c_str(), summary.faults);
    return 1;
  }
  return 0;
}

std::atomic<bool> g_stop{false};  // set from the signal handler; read by the device loop
void on_signal(int) { g_stop = true; }

int run_devices(const std::string& scenario_path, const std::string& board_path,
                RealtimeDevicesOptions options) {
  const Scenario scenario = load_scenario_warned(scenario_path, board_path);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  const RealtimeDevicesResult r = run_realtime_devices(scenario, options, g_stop);
  std::printf(
      "devices ran %.1f s: %.2f m, %d seedlings planted; CAN in %llu out %llu lost %llu; "
      "gpio writes %u; link downs %u reopens %u; late steps %llu\n",
      r.seconds, r.distance_m, r.seedlings_planted, static_cast<unsigned long long>(r.frames_in),
      static_cast<unsigned long long>(r.frames_out), static_cast<unsigned long long>(r.frames_lost),
      r.gpio_writes, r.link_downs, r.reopens, static_cast<unsigned long long>(r.late_steps));
  return 0;
}

// The [effects] keys a scenario may set: what each hides in the plant, its range and unit.
int print_effect_keys() {
  std::printf("[effects] keys of a scenario (all off by default; docs/adding-an-effect.md):\n");
  for (const EffectKey& k : kEffectKeys) {
    char range[64];
    std::snprintf(range, sizeof range, "%g to %g %s", k.min, k.max, k.unit);
    std::printf("  %-28s %-24s %s\n", k.key, range, k.what);
  }
  return 0;
}

// A subcommand and what it runs once parsed; its options live in the closure.
struct Command {
  CLI::App* sub = nullptr;
  std::function<int()> run;
};

Command add_run(CLI::App& app) {
  struct Opts {
    std::string scenario, out = "out";
    bool quiet = false, force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* run = app.add_subcommand("run", "run a scenario: recording.csv, summary.json, report.html");
  run->add_option("scenario", o->scenario, "scenario file (TOML)")->required();
  run->add_option("--out", o->out, "output directory")->capture_default_str();
  run->add_flag("--quiet", o->quiet, "do not print the summary");
  run->add_flag("--force", o->force, "replace --out even if it holds something other than a run");
  return {run, [o] { return run_scenario(o->scenario, o->out, o->quiet, o->force); }};
}

#ifdef PLANTER_WITH_SWEEP
Command add_sweep(CLI::App& app) {
  struct Opts {
    std::string scenario, out = "out";
    SweepOptions sweep;
  };
  auto o = std::make_shared<Opts>();
  SweepOptions& so = o->sweep;
  auto* sweep = app.add_subcommand(
      "sweep", "the paper's Box-Behnken experiment: replicated runs, response surfaces, optimum");
  sweep->add_option("scenario", o->scenario, "base scenario file (TOML)")->required();
  sweep->add_option("--out", o->out, "output directory")->capture_default_str();
  sweep->add_flag("--force", so.force,
                  "replace --out even if it holds something other than a sweep");
  sweep->add_option("--distance", so.distance_m, "metres per run")
      ->capture_default_str()
      ->check(planter::config::finite_range(0.5, 1000.0));
  sweep->add_option("--replicates", so.replicates, "runs per design point, at least")
      ->capture_default_str()
      ->check(planter::config::finite_range(1, 50));
  sweep
      ->add_option("--max-replicates", so.max_replicates,
                   "runs per design point, at most, while its damage rate is not resolved")
      ->capture_default_str()
      ->check(planter::config::finite_range(1, 200));
  sweep
      ->add_option("--damage-precision", so.damage_precision_pts,
                   "goal for the standard error of each point's damage rate, in points")
      ->capture_default_str()
      ->check(planter::config::finite_range(0.01, 50.0));
  sweep->add_option("--jobs", so.jobs, "runs at a time (0: one per core)")
      ->capture_default_str()
      ->check(planter::config::finite_range(0, 256));
  planter::apps::add_executor_options(*sweep, so.executor);
  return {sweep, [o] {
            o->sweep.max_replicates = std::max(o->sweep.max_replicates, o->sweep.replicates);
            return run_sweep(o->scenario, o->out, o->sweep);
          }};
}

Command add_sensitivity(CLI::App& app) {
  auto o = add_study<SensitivityOptions>(
      app, "sensitivity",
      "which model values the figures rest on: Morris elementary effects over their ranges");
  o->cmd->add_option("--trajectories", o->options.trajectories, "Morris's r")
      ->capture_default_str()
      ->check(planter::config::finite_range(2, 100));
  o->cmd->add_flag("--optimum", o->options.optimum,
                   "also run the paper's design (15 runs) at each point: the optimum's spread");
  return {o->cmd, [o] { return run_sensitivity(o->scenario, o->out, o->options); }};
}

Command add_monte_carlo(CLI::App& app) {
  auto o = add_study<MonteCarloOptions>(
      app, "montecarlo",
      "what the figures may be given what is not known: every model value drawn across its "
      "range (Latin hypercube), a seed a run");
  o->cmd->add_option("--runs", o->options.runs, "runs (seasons) to draw")
      ->capture_default_str()
      ->check(planter::config::finite_range(2, 100000));
  o->cmd->add_flag("--grip", o->options.grip,
                   "also run each draw at every constant clamp force of the sweep's "
                   "trade-off: does gripping each stem halve the damage?");
  o->cmd->add_option("--stems-mm", o->options.stems_mm,
                     "stems of this diameter range in every run, MIN-MAX (e.g. 5-15)");
  return {o->cmd, [o] { return run_monte_carlo(o->scenario, o->out, o->options); }};
}

Command add_robustness(CLI::App& app) {
  auto o = add_study<RobustnessOptions>(
      app, "robustness",
      "the controller under disturbance: each loop held, alarmed or silent, case by case, "
      "beside the paper's drive");
  o->cmd
      ->add_option("--combinations", o->options.combinations,
                   "random combinations of disturbances (Latin hypercube)")
      ->capture_default_str()
      ->check(planter::config::finite_range(0, 10000));
  return {o->cmd, [o] { return run_robustness(o->scenario, o->out, o->options); }};
}
#endif

Command add_plan_run(CLI::App& app) {
  struct Opts {
    std::string plan;
    std::size_t index = 0;
  };
  auto o = std::make_shared<Opts>();
  auto* plan_run = app.add_subcommand(
      "plan-run", "run one run of a plan (what each local process or Slurm task executes)");
  plan_run->add_option("plan", o->plan, "plan.json")->required();
  plan_run->add_option("index", o->index, "the run's index in the plan")
      ->required()
      ->check(planter::config::whole_number());
  return {plan_run, [o] {
            execute_planned_run(o->plan, o->index, planter::apps::version());
            return 0;
          }};
}

Command add_values(CLI::App& app) {
  auto scenario = std::make_shared<std::string>();
  auto* values = app.add_subcommand(
      "values", "every model value the conclusions rest on: value, unit, range, origin, source");
  values->add_option("scenario", *scenario, "scenario file (default: the built-in values)");
  return {values, [scenario] {
            const PlantConfig plant =
                scenario->empty() ? PlantConfig{} : load_scenario(*scenario).plant;
            std::printf("%-40s %9s %-7s %19s %-10s %s\n", "value", "in use", "unit",
                        "plausible range", "origin", "source");
            std::fputs(model_values_text(plant).c_str(), stdout);
            return 0;
          }};
}

Command add_devices(CLI::App& app) {
  struct Opts {
    std::string scenario, board;
    RealtimeDevicesOptions devices;
  };
  auto o = std::make_shared<Opts>();
  RealtimeDevicesOptions& d = o->devices;
  auto* devices = app.add_subcommand(
      "devices", "the plant and its CANopen nodes in real time on a real CAN bus and gpio-sim");
  devices->add_option("scenario", o->scenario, "scenario file (TOML)")->required();
  devices->add_option("--can", d.can_interface, "SocketCAN interface")->required();
  devices->add_option("--gpio", d.gpio_chip, "gpio-sim chip (name, path or label)")->required();
  devices->add_option("--board", o->board, "board file (default: the scenario's)");
  devices->add_option("--truth", d.truth_path, "write ground truth CSV here");
  devices->add_option("--duration", d.duration_s, "seconds (0 = whole route)")
      ->check(planter::config::finite_range(0.0, 1e6));
  return {devices, [o] { return run_devices(o->scenario, o->board, o->devices); }};
}

#ifdef PLANTER_WITH_CONSOLE
Command add_live(CLI::App& app) {
  struct Opts {
    std::string scenario;
    LiveOptions live;
  };
  auto o = std::make_shared<Opts>();
  LiveOptions& lo = o->live;
  auto* live = app.add_subcommand(
      "live", "the simulated machine in real time, with the operator's console in a browser");
  live->add_option("scenario", o->scenario, "scenario file (TOML)")->required();
  live->add_option("--port", lo.console.port, "TCP port of the console (0: any free)")
      ->capture_default_str()
      ->check(planter::config::finite_range(0, 65535));
  live->add_option("--bind", lo.console.bind,
                   "address to serve on (0.0.0.0: every network of this machine)")
      ->capture_default_str();
  live->add_option("--duration", lo.duration_s, "simulated seconds (0: until Ctrl-C)")
      ->capture_default_str()
      ->check(planter::config::finite_range(0.0, 1e6));
  live->add_option("--speed", lo.speed, "simulated seconds per wall-clock second")
      ->capture_default_str()
      ->check(planter::config::finite_range(0.1, 100.0));
  live->add_option("--dir", lo.dir, "where the console's recordings (recordings/) and audit.log go")
      ->capture_default_str();
  live->add_option("--pairing-secret-file", lo.pairing_secret_file,
                   "the operator's pairing secret (default: a new one, shown on the terminal)");
  live->add_option("--viewer-secret-file", lo.viewer_secret_file,
                   "viewing needs this secret (default: viewing is open)");
  live->add_flag("--view-only", lo.view_only, "the console takes no command");
  return {live, [o] { return run_live(o->scenario, o->live); }};
}
#endif

#ifdef PLANTER_WITH_REPLAY
Command add_replay(CLI::App& app) {
  struct Opts {
    std::string model, recording, out = "out";
    bool force = false;
  };
  auto o = std::make_shared<Opts>();
  auto* replay = app.add_subcommand(
      "replay", "run planter-fit's augmented model (model.toml) on a recording's inputs");
  replay->add_option("model", o->model, "model.toml from planter-fit")->required();
  replay->add_option("recording", o->recording, "recording CSV")->required();
  replay->add_option("--out", o->out, "output directory (replay.csv)")->capture_default_str();
  replay->add_flag("--force", o->force,
                   "replace --out even if it holds something other than a replay");
  return {replay, [o] { return run_replay(o->model, o->recording, o->out, o->force); }};
}
#endif

// The parsed subcommand run, each failure one line on stderr and its exit code.
int run_parsed(const std::vector<Command>& commands) {
  try {
    for (const Command& c : commands)
      if (*c.sub) return c.run();
#ifdef PLANTER_WITH_REPLAY
  } catch (const analysis::RecordingError& e) {
    std::fprintf(stderr, "planter-sim: %s\n", e.what());
    return 2;
#endif
  } catch (const config::ConfigError& e) {
    std::fprintf(stderr, "planter-sim: %s\n", e.what());
    return 2;
  } catch (const PlanWritten& w) {
    // --plan-only: the first plan is written; the rest of the work follows from its results.
    std::printf(
        "plan written: %s/plan.json\nrun it: %s\nthen run this command again (without "
        "--plan-only) to gather the runs and plan what follows from them\n",
        w.dir.c_str(), w.how_to_run.c_str());
    return 0;
  } catch (const hal::linux_backend::HalError& e) {
    std::fprintf(stderr, "planter-sim: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "planter-sim: %s\n", e.what());
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"planter-sim: the transplanter's plant model and lockstep simulation runner"};
  app.set_version_flag("--version", std::string("planter-sim ") + planter::apps::version());
  planter::apps::add_list_keys_flag(app, planter::sim::kScenarioFileKeys,
                                    "a scenario and of a seedling force model");
  app.require_subcommand(1);
  std::vector<Command> commands{add_run(app)};
#ifdef PLANTER_WITH_SWEEP
  commands.push_back(add_sweep(app));
  commands.push_back(add_sensitivity(app));
  commands.push_back(add_monte_carlo(app));
  commands.push_back(add_robustness(app));
#endif
  commands.push_back(add_plan_run(app));
  commands.push_back(add_values(app));
  commands.push_back(
      {app.add_subcommand("effects", "list the [effects] keys a scenario may set to hide physics"),
       print_effect_keys});
  commands.push_back(add_devices(app));
#ifdef PLANTER_WITH_CONSOLE
  commands.push_back(add_live(app));
#endif
#ifdef PLANTER_WITH_REPLAY
  commands.push_back(add_replay(app));
#endif
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return planter::apps::parse_ended(app, e, "planter-sim", argc, argv, 2);
  }
  return run_parsed(commands);
}
