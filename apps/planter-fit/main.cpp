// planter-fit RECORDING.csv [--model MODEL.toml] [--out DIR] [--json] [--jobs N]
// Calibrates the nominal model of every observable subsystem, locates the mismatch, names
// the missing physics from a library of effects, refits it and shows the held-out error.
// Exit codes: 0 done (whatever the verdict), 1 an output could not be written, 2 bad input.
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "analysis/day_tracks.h"
#include "analysis/fit_outputs.h"
#include "analysis/model_file.h"
#include "apps/version/cli_errors.h"
#include "apps/version/version.h"
#include "config/cli_range.h"
#include "config/config_error.h"
#include "config/output_set.h"

namespace {

using namespace planter::analysis;

int fail(int code, const std::string& message) {
  std::fprintf(stderr, "planter-fit: %s\n", message.c_str());
  return code;
}

// The recording: its rows and rate, what was left out, and the known inputs.
void print_recording(const FitReport& r) {
  if (r.day)
    std::printf(
        "recording: %s, %zu rows, %.1f s: the first %zu rows searched, the model then tracked "
        "across %zu windows\n",
        r.file.c_str(), r.day->rows, r.day->duration_s, r.rows, r.day->windows);
  if (r.day && r.day->untracked_rows > 0)
    std::printf("the last %zu rows are under a quarter window: not tracked\n",
                r.day->untracked_rows);
  std::printf(
      "%s: %s, %zu rows at %.4g Hz (%zu analysed, up to %.3g Hz), %.1f s (held out from "
      "%.1f s)\n",
      r.day ? "first window" : "recording", r.file.c_str(), r.rows, r.rate_hz, r.analysed_rows,
      r.analysed_up_to_hz, r.duration_s, r.held_out_from_s);
  if (!r.stopped_state.empty())
    std::printf(
        "the machine entered '%s' at %.2f s: the %zu rows from there on are left out (its drives "
        "are disabled and a silent node's values stale: the supervisor's to report, not physics)\n",
        r.stopped_state.c_str(), r.stopped_at_s, r.stopped_rows);
  for (const auto& u : r.unobservable) std::printf("not observable: %s\n", u.c_str());
  if (!r.known_inputs.empty()) {
    std::printf("known disturbances the recording carries, taken as inputs:");
    for (const auto& k : r.known_inputs)
      std::printf("%s %s", &k == &r.known_inputs.front() ? "" : ",", k.c_str());
    std::printf("\n");
  }
  if (!r.glitches.empty()) {
    std::printf("excluded %zu single-sample glitch(es), replaced by their neighbours' mean:",
                r.glitches.size());
    for (std::size_t k = 0; k < r.glitches.size() && k < 5; ++k)
      std::printf(" %s = %.6g at %.3f s;", r.glitches[k].column.c_str(), r.glitches[k].value,
                  r.glitches[k].t_s);
    if (r.glitches.size() > 5) std::printf(" ... (all in fit.json)");
    std::printf("\n");
  }
}

// A channel's change point: when, and which parameter moved (or which it cannot tell).
void print_change(const ChannelReport& c) {
  std::printf("    a parameter changed at t = %.1f +- %.1f s:", c.change->at_s, c.change->at_sd_s);
  for (const auto& m : c.change->changed)
    std::printf("%s%s %.4g -> %.4g",
                &m == &c.change->changed.front() ? " "
                : c.change->tied                 ? ", or "
                                                 : ", ",
                m.name.c_str(), m.before, m.after);
  if (c.change->tied)
    std::printf(" (this recording cannot tell which: a sweep of %s over its range would)",
                c.channel->input().c_str());
  std::printf("\n");
}

// What a channel's fit found: its effects, process, change, tones and ties.
void print_findings(const FitReport& r, const ChannelReport& c) {
  for (std::size_t e = 0; e < c.final_fit.effects.size(); ++e)
    std::printf("    %s\n", effect_text(c, e).c_str());
  if (!c.degenerate.empty()) std::printf("    %s\n", c.degenerate.c_str());
  if (const std::string idle = not_exercised(c); !idle.empty())
    std::printf("    not exercised by this recording, so not fitted: %s\n", idle.c_str());
  if (c.logged_step > 0.0)
    std::printf(
        "    %s is recorded in steps of %.3g: their rounding, %.3g RMS, is the floor no "
        "model matches closer than (not noise, not a mismatch)\n",
        c.channel->output().c_str(), c.logged_step, c.resolution_rms);
  if (c.disturbance)
    std::printf("    %s (the process gives its one-step predictions a held-out RMS of %.3g)\n",
                c.disturbance->describe().c_str(), c.disturbance->predicted_held_out);
  for (const auto& note : c.beside_disturbance) std::printf("    %s\n", note.c_str());
  for (const auto& note : c.refined) std::printf("    %s\n", note.c_str());
  if (c.change) print_change(c);
  for (const auto& f : c.fast_tones) {
    std::printf(
        "    periodic disturbance (vibration) above the analysed %.3g Hz: frequency_hz = "
        "%.4g",
        r.analysed_up_to_hz, f.tone.frequency_hz);
    if (f.order > 1) std::printf(" (order %d of %.4g Hz)", f.order, f.fundamental_hz);
    std::printf(" amplitude = %.4g; held-out RMS %.4g -> %.4g\n", f.tone.amplitude,
                f.held_out_rms_before, f.held_out_rms_after);
  }
  for (const auto& tie : c.ties)
    std::printf(
        "    %s or %s: this recording cannot separate them (BIC %+.1f); to tell them "
        "apart, record %s\n",
        tie.chosen.c_str(), tie.alternative.c_str(), tie.delta_bic, tie.experiment.c_str());
}

// What a channel's fit could not settle: across the day, undetermined, at a range's edge,
// unexplained.
void print_doubts(const FitReport& r, const ChannelReport& c) {
  if (r.day) {
    const ChannelDay& d = r.day->channels[static_cast<std::size_t>(&c - r.channels.data())];
    std::printf("    across %zu windows of %.0f s: %s\n", r.day->windows, r.day->window_s,
                d.verdict.c_str());
  }
  if (!c.undetermined.empty())
    std::printf(
        "    not determined by the calibration part: %s; record the regime the held-out "
        "part shows within the calibration part to determine it\n",
        c.undetermined.c_str());
  for (const std::string& edge : c.at_range_edge)
    std::printf("    at the edge of its range: %s\n", edge.c_str());
  if (c.unexplained) {
    std::printf(
        "    unexplained: worst window at %.0f s (%.1fx), input correlation %.2f, "
        "spectrum peak %.2f Hz\n",
        c.location.worst_window_start_s, c.location.worst_window_ratio,
        c.location.input_correlation, c.location.dominant_frequency_hz);
  }
}

void print_summary(const FitReport& r, double wall_s, double nominal_pass_s) {
  print_recording(r);
  for (const auto& c : r.channels) {
    std::printf("%-10s %-12s %-26s held-out RMS %.4g -> %.4g%s (noise %.3g",
                c.channel->subsystem().c_str(), c.channel->output().c_str(), c.verdict.c_str(),
                c.nominal.rms_held_out, held_out_after(c), c.disturbance ? " one step ahead" : "",
                c.noise_rms);
    if (c.input_noise_rms > 0.0) std::printf(", from the input's noise %.3g", c.input_noise_rms);
    std::printf(")\n");
    print_findings(r, c);
    print_doubts(r, c);
  }
  std::printf("analysis: %.2f s wall, %.0fx one nominal simulation pass of all rows (%.4f s)\n",
              wall_s, nominal_pass_s > 0 ? wall_s / nominal_pass_s : 0.0, nominal_pass_s);
}

// Progress on a terminal: one status line, rewritten at each step of a channel (the clamp's
// runs for seconds) and as each channel ends.
void show_progress(FitOptions& o) {
  auto done_so_far = std::make_shared<std::pair<std::mutex, std::size_t>>();
  o.on_channel_done = [done_so_far](std::size_t done, std::size_t total,
                                    const std::string& channel) {
    const std::lock_guard<std::mutex> lock(done_so_far->first);
    done_so_far->second = done;
    std::fprintf(stderr, "\rplanter-fit: %zu of %zu channels analysed (last: %s)\x1b[K%s", done,
                 total, channel.c_str(), done == total ? "\n" : "");
  };
  o.on_step = [done_so_far](const std::string& channel, const std::string& step) {
    const std::lock_guard<std::mutex> lock(done_so_far->first);
    std::fprintf(stderr, "\rplanter-fit: %zu channels analysed; %s: %s\x1b[K", done_so_far->second,
                 channel.c_str(), step.c_str());
  };
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{
      "planter-fit: locate, name and model the physics a recording shows and the "
      "nominal model lacks"};
  app.set_version_flag("--version", std::string("planter-fit ") + planter::apps::version());
  std::string file, out = "fit-out";
  bool json = false;
  int jobs = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  app.add_option("recording", file, "recording CSV (docs/recording-format.md)")->required();
  std::string model;
  app.add_option("--model", model,
                 "a model.toml to start from: its values and effects are taken as known")
      ->check(CLI::ExistingFile);
  app.add_option("--out", out, "output directory (fit.json, report.html, model.toml)");
  app.add_flag("--json", json, "print fit.json instead of the summary");
  bool force = false;
  app.add_flag("--force", force, "replace --out even if it holds something other than a fit");
  app.add_option("--jobs", jobs, "channels analysed at once")
      ->check(planter::config::finite_range(1, 256));
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return planter::apps::parse_ended(app, e, "planter-fit", argc, argv, 2);
  }
  try {
    const auto t0 = std::chrono::steady_clock::now();
    FitOptions o;
    o.jobs = jobs;
    if (isatty(STDERR_FILENO)) show_progress(o);  // logs and pipes get the summary alone
    // The first window (the whole of a shorter recording) is read and analysed; the rest of a
    // longer one is read a window at a time and the model tracked across it.
    RecordingReader reader(file);
    Recording rec;
    reader.read(rec, o.window_rows);
    reader.require_rows(rec, 50);
    planter::config::OutputSet outputs(out, "planter-fit", force);  // refuses before the work
    if (!model.empty()) o.start_model = load_augmented_model(model);
    // The first channels take the longest (the clamp's, with every effect tried): say the work
    // has begun, on a terminal, before the first one ends.
    if (isatty(STDERR_FILENO))
      std::fprintf(stderr,
                   "planter-fit: %zu rows read (%zu columns); fitting each channel's nominal "
                   "model, then the effects it lacks (the first channel takes longest)\n",
                   rec.t.size(), rec.signals.size());
    FitReport rep = analyse(rec, o);
    if (reader.more()) rep.day = track_day(reader, rec, rep, o);
    const Recording analysed = analysed_rows_of(rec, rep);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    // One nominal simulation pass of every analysed channel over the whole recording (all its
    // rows, as a simulator would run it), for the ratio.
    const auto p0 = std::chrono::steady_clock::now();
    for (const auto& c : rep.channels) {
      std::vector<double> y;
      c.channel->simulate(rec, c.nominal.nominal, {}, y);
    }
    const double pass =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - p0).count();
    const std::string fit_text = write_fit_outputs(outputs, rep, analysed, wall);
    if (json)
      std::fputs(fit_text.c_str(), stdout);
    else
      print_summary(rep, wall, pass);
    return 0;
  } catch (const RecordingError& e) {
    return fail(2, e.what());
  } catch (const planter::config::ConfigError& e) {
    return fail(2, e.what());
  } catch (const std::exception& e) {
    return fail(1, e.what());
  }
}
