#include "apps/planter-can/cmd_calibrate.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <ostream>

#include "apps/planter-can/board_file_edit.h"
#include "apps/planter-can/operator_prompt.h"
#include "apps/planter-can/sdo_session.h"
#include "config/board_keys.h"
#include "firmware/canopen/cia402.h"
#include "firmware/canopen/pdo.h"
#include "firmware/io/signal_table.h"
#include "firmware/sensing/quadrature_decoder.h"

namespace planter::cantool {
namespace {

namespace c402 = canopen::cia402;

// One calibrated value: its row of the calibration's key table (config/board_keys.h), the
// value in use and the measured one.
struct Change {
  const config::ConfigKey& row;
  double before = 0.0, after = 0.0;
};

consteval const config::ConfigKey& ck(std::string_view dotted) {
  return config::key_in(config::kCalibrationKeys, dotted);
}

std::string number_text(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", v);
  return b;
}

int report(ToolContext& ctx, const CalibrateOptions& opt, const std::vector<Change>& changes,
           const nlohmann::json& evidence) {
  std::string write_error, backup, written_file;
  bool written = false;
  if (opt.write) {
    std::vector<BoardEdit> edits;
    for (const auto& c : changes)
      edits.push_back({std::string(c.row.table), std::string(c.row.name), number_text(c.after)});
    written = write_board_edits(ctx.board->file, edits, write_error, &backup, &written_file);
  }
  if (ctx.json) {
    nlohmann::json j{{"calibration", opt.what}, {"evidence", evidence}, {"written", written}};
    if (written) {
      j["file"] = written_file;
      j["backup"] = backup;
    }
    for (const auto& c : changes) {
      j["changes"].push_back({{"table", c.row.table},
                              {"key", c.row.name},
                              {"before", c.before},
                              {"after", c.after},
                              {"unit", c.row.unit}});
    }
    if (!write_error.empty()) j["error"] = write_error;
    ctx.out << j.dump(2) << "\n";
  } else {
    char line[256];
    std::snprintf(line, sizeof line, "%-28s %14s %14s  %s\n", "key", "before", "after", "unit");
    ctx.out << line;
    for (const auto& c : changes) {
      std::snprintf(line, sizeof line, "%-28s %14.6g %14.6g  %s\n",
                    config::dotted_name(c.row).c_str(), c.before, c.after,
                    std::string(c.row.unit).c_str());
      ctx.out << line;
    }
    if (written)
      ctx.out << "written to " << written_file << " (previous kept as " << backup << ")\n";
    if (!opt.write) ctx.out << "not written (" << opt.not_written_because << ")\n";
  }
  if (!write_error.empty()) {
    ctx.err << "planter-can: calibrate: " << write_error << "\n";
    return kExitFailed;
  }
  return kExitOk;
}

// Mean of `samples` SDO reads of the force sensor's process value, in counts.
bool read_force_counts(ToolContext& ctx, const NodeConfig& n, int samples, double& mean,
                       double& sd) {
  SdoSession sdo(ctx.link, ctx.sdo_timeout_ns);
  // Let a freshly hung weight stop swinging (and the sensor's filter settle) first.
  ctx.link.idle_until(ctx.link.now_ns() + 500'000'000);
  double sum = 0, sum2 = 0;
  for (int i = 0; i < samples; ++i) {
    const SdoResult r = sdo.read(n.node_id, 0x7130, 1);
    if (!r.ok()) {
      ctx.err << "planter-can: calibrate: reading 7130:01 of node " << unsigned{n.node_id} << ": "
              << r.error_text(n.node_id, ctx.sdo_timeout_ns) << "\n";
      return false;
    }
    const auto v = static_cast<double>(canopen::sign_extend(r.value(), 16));
    sum += v;
    sum2 += v * v;
    // Spread the samples over time so the sensor's noise averages out.
    ctx.link.idle_until(ctx.link.now_ns() + 10'000'000);
  }
  mean = sum / samples;
  sd = std::sqrt(std::max(0.0, sum2 / samples - mean * mean));
  return true;
}

int calibrate_force(ToolContext& ctx, const CalibrateOptions& opt, OperatorPrompt& person) {
  if (!(opt.known_N > 0.0)) {
    ctx.err << "planter-can: calibrate force needs --known-N, the weight in newtons (> 0)\n";
    return kExitBadInput;
  }
  const NodeConfig& n = ctx.board->controller.node(NodeRole::kForceSensor);
  double zero = 0, zero_sd = 0, loaded = 0, loaded_sd = 0;
  if (!person.ask("take every load off the clamp force sensor (open the roller)",
                  OperatorAction::kRemoveLoad, 0.0) ||
      !read_force_counts(ctx, n, opt.samples, zero, zero_sd))
    return kExitFailed;
  if (!person.ask("hang the " + number_text(opt.known_N) + " N weight on the force sensor",
                  OperatorAction::kHangWeight, opt.known_N) ||
      !read_force_counts(ctx, n, opt.samples, loaded, loaded_sd))
    return kExitFailed;
  person.ask("take the weight off", OperatorAction::kRemoveLoad, 0.0);
  const double span = (loaded - zero) / opt.known_N;
  if (std::fabs(loaded - zero) < 5.0 * std::max(1.0, zero_sd + loaded_sd)) {
    ctx.err << "planter-can: calibrate force: the reading changed by " << (loaded - zero)
            << " counts only (noise " << zero_sd << "); was the weight hung?\n";
    return kExitFailed;
  }
  std::vector<Change> changes{{ck("nodes.force_sensor.zero_counts"), n.zero_counts, zero},
                              {ck("nodes.force_sensor.counts_per_unit"), n.counts_per_unit, span}};
  const double before_N = bus_to_si(BusScale::kTared, n, loaded);
  nlohmann::json ev{{"zero_counts_mean", zero},     {"zero_counts_sd", zero_sd},
                    {"loaded_counts_mean", loaded}, {"loaded_counts_sd", loaded_sd},
                    {"known_N", opt.known_N},       {"weight_read_before_N", before_N},
                    {"samples", opt.samples}};
  if (!ctx.json) {
    char line[160];
    std::snprintf(line, sizeof line, "the %.3g N weight read %.2f N with the old calibration\n",
                  opt.known_N, before_N);
    ctx.out << line;
  }
  return report(ctx, opt, changes, ev);
}

int calibrate_soil_wheel(ToolContext& ctx, const CalibrateOptions& opt, OperatorPrompt& person) {
  if (!(opt.distance_m > 0.0)) {
    ctx.err
        << "planter-can: calibrate soil-wheel needs --distance-m, the measured distance (> 0)\n";
    return kExitBadInput;
  }
  hal::GpioEdgeSource* edges = ctx.link.encoder();
  if (edges == nullptr) {
    ctx.err << "planter-can: calibrate soil-wheel needs the encoder lines (run it on the board)\n";
    return kExitFailed;
  }
  const EncoderConfig& enc = ctx.board->controller.encoder;
  QuadratureDecoder decoder(enc.glitch_filter_ns);
  hal::GpioEdge e;
  while (edges->next_edge(e)) {
  }  // whatever happened before the prompt does not count
  if (!person.ask("push the machine straight along the measured " + number_text(opt.distance_m) +
                      " m, then stop",
                  OperatorAction::kPushMachine, opt.distance_m))
    return kExitFailed;
  Progress progress(ctx.err, ctx.progress);
  const std::int64_t t0 = ctx.link.now_ns();
  const auto still_ns = static_cast<std::int64_t>(opt.still_s * 1e9);
  bool moved = false;
  for (;;) {
    const std::int64_t now = ctx.link.now_ns();
    while (edges->next_edge(e)) decoder.on_edge(e);
    if (decoder.count() != 0) moved = true;
    if (moved && now - decoder.last_count_time_ns() >= still_ns) break;
    if (now - t0 > static_cast<std::int64_t>(opt.max_wait_s * 1e9)) {
      ctx.err << "planter-can: calibrate soil-wheel: "
              << (moved ? "the wheel never came to rest" : "the wheel never turned") << " within "
              << opt.max_wait_s << " s\n";
      return kExitFailed;
    }
    ctx.link.idle_until(now + 10'000'000);
    progress.update("counting: " + std::to_string(decoder.count()) + " counts");
  }
  progress.done();
  const double counts = static_cast<double>(decoder.count());
  // Each invalid A/B transition is at least one lost edge: past 0.2 % the figure is not
  // trustworthy, so nothing is written.
  const double lost_share = 2.0 * decoder.invalid_transitions() / std::max(1.0, std::fabs(counts));
  if (lost_share > 0.002) {
    ctx.err << "planter-can: calibrate soil-wheel: " << decoder.invalid_transitions()
            << " invalid A/B transitions in " << decoder.count()
            << " counts: encoder edges were lost (push slower, or check the wiring and the "
               "glitch filter); nothing written\n";
    return kExitFailed;
  }
  const double counts_per_m = std::fabs(counts) / opt.distance_m;
  const double radius = wheel_radius_for_counts_per_m(enc.counts_per_rev, counts_per_m);
  const double before_counts_per_m = 1.0 / metres_per_count(enc);
  nlohmann::json ev{{"counts", decoder.count()},
                    {"distance_m", opt.distance_m},
                    {"counts_per_m", counts_per_m},
                    {"counts_per_m_before", before_counts_per_m},
                    {"direction", counts >= 0 ? "forward" : "reversed (A/B swapped?)"},
                    {"invalid_transitions", decoder.invalid_transitions()},
                    {"glitches", decoder.glitches()}};
  if (!ctx.json) {
    char line[200];
    std::snprintf(line, sizeof line, "%lld counts over %.3f m: %.1f counts/m (board said %.1f)%s\n",
                  static_cast<long long>(decoder.count()), opt.distance_m, counts_per_m,
                  before_counts_per_m, counts < 0 ? "; counts ran backwards: A/B swapped?" : "");
    ctx.out << line;
  }
  std::vector<Change> changes{{ck("encoder.wheel_radius_m"), enc.wheel_radius_m, radius}};
  return report(ctx, opt, changes, ev);
}

// Drives a CiA 402 actuator over SDO (no PDOs needed): enable, move, wait.
class SdoDrive {
 public:
  SdoDrive(ToolContext& ctx, const NodeConfig& n)
      : ctx_(ctx), n_(n), sdo_(ctx.link, ctx.sdo_timeout_ns) {}
  bool write(std::uint16_t index, std::uint32_t value, std::size_t size) {
    const SdoResult r = sdo_.write_u32(n_.node_id, index, 0, value, size);
    if (!r.ok())
      error_ = "writing " + object(index) + ": " + r.error_text(n_.node_id, ctx_.sdo_timeout_ns);
    return r.ok();
  }
  bool read(std::uint16_t index, std::int64_t& value, unsigned bits) {
    const SdoResult r = sdo_.read(n_.node_id, index, 0);
    if (!r.ok())
      error_ = "reading " + object(index) + ": " + r.error_text(n_.node_id, ctx_.sdo_timeout_ns);
    value = canopen::sign_extend(r.value(), bits);
    return r.ok();
  }
  bool enable() {
    return write(c402::kControlword, c402::controlword::kShutdown, 2) &&
           write(c402::kControlword, c402::controlword::kSwitchOn, 2) &&
           write(c402::kControlword, c402::controlword::kEnableOperation, 2);
  }
  bool disable() { return write(c402::kControlword, c402::controlword::kShutdown, 2); }
  // A new set-point (or the homing start): rising edge of controlword bit 4.
  bool trigger() {
    return write(c402::kControlword, c402::controlword::kEnableOperation, 2) &&
           write(c402::kControlword,
                 c402::controlword::kEnableOperation | c402::controlword::kNewSetPoint |
                     c402::controlword::kChangeImmediately,
                 2);
  }
  void pause_ms(int ms) { ctx_.link.idle_until(ctx_.link.now_ns() + std::int64_t{ms} * 1'000'000); }
  [[nodiscard]] const std::string& error() const { return error_; }

 private:
  static std::string object(std::uint16_t index) {
    char b[16];
    std::snprintf(b, sizeof b, "%04X", index);
    return b;
  }
  ToolContext& ctx_;
  const NodeConfig& n_;
  SdoSession sdo_;
  std::string error_;
};

int calibrate_depth(ToolContext& ctx, const CalibrateOptions& opt) {
  const NodeConfig& n = ctx.board->controller.node(NodeRole::kDepthActuator);
  const DepthLoopConfig& depth = ctx.board->controller.depth;
  SdoDrive drive(ctx, n);
  Progress progress(ctx.err, ctx.progress);
  auto fail = [&](const std::string& what) {
    progress.done();
    drive.disable();
    ctx.err << "planter-can: calibrate depth: " << what << "\n";
    return kExitFailed;
  };
  // 1. Homing (mode 6) on the lower end stop.
  if (!drive.write(c402::kModesOfOperation, static_cast<std::uint8_t>(c402::kModeHoming), 1) ||
      !drive.enable() || !drive.trigger())
    return fail(drive.error());
  const std::int64_t t0 = ctx.link.now_ns();
  std::int64_t status = 0;
  for (;;) {
    if (!drive.read(c402::kStatusword, status, 16)) return fail(drive.error());
    if ((status & c402::statusword::kSetPointAcknowledge) != 0) break;  // homing attained
    if (ctx.link.now_ns() - t0 > 60'000'000'000) return fail("homing did not finish within 60 s");
    progress.update("homing...");
    drive.pause_ms(50);
  }
  std::int64_t home = 0;
  if (!drive.read(c402::kPositionActual, home, 32)) return fail(drive.error());
  // 2. Travel: up to the board's upper limit, slowly; where it stops is the end stop.
  if (!drive.write(c402::kModesOfOperation, static_cast<std::uint8_t>(c402::kModeProfilePosition),
                   1) ||
      !drive.enable() ||
      !drive.write(
          c402::kTargetPosition,
          static_cast<std::uint32_t>(std::llround(si_to_bus(BusScale::kPerCount, n, depth.max_mm))),
          4) ||
      !drive.trigger())
    return fail(drive.error());
  std::int64_t pos = 0;
  std::int64_t last = 0;
  bool have_last = false;
  int still = 0;
  const std::int64_t t1 = ctx.link.now_ns();
  for (;;) {
    drive.pause_ms(100);
    if (!drive.read(c402::kPositionActual, pos, 32)) return fail(drive.error());
    if (std::llabs(pos - std::llround(si_to_bus(BusScale::kPerCount, n, depth.max_mm))) < 20)
      break;  // reached
    still =
        have_last && std::llabs(pos - last) < std::llround(si_to_bus(BusScale::kPerCount, n, 0.05))
            ? still + 1
            : 0;
    if (still >= 5) break;  // 0.5 s without moving: the end stop
    last = pos;
    have_last = true;
    if (ctx.link.now_ns() - t1 > 120'000'000'000) return fail("travel did not end within 120 s");
    progress.update(
        "travel: " + number_text(bus_to_si(BusScale::kPerCount, n, static_cast<double>(pos))) +
        " mm");
  }
  const double top_mm = bus_to_si(BusScale::kPerCount, n, static_cast<double>(pos));
  // 3. Back to the raised position and disabled.
  if (!drive.write(c402::kTargetPosition,
                   static_cast<std::uint32_t>(
                       std::llround(si_to_bus(BusScale::kPerCount, n, depth.raised_mm))),
                   4) ||
      !drive.trigger())
    return fail(drive.error());
  drive.pause_ms(100);
  progress.done();
  const bool reached = top_mm >= depth.max_mm - 0.05;
  nlohmann::json ev{{"home_counts", home},
                    {"travel_top_mm", top_mm},
                    {"board_max_mm", depth.max_mm},
                    {"reached_board_max", reached}};
  if (!ctx.json) {
    char line[200];
    std::snprintf(
        line, sizeof line, "homed at %lld counts; travel %s at %.2f mm (board max %.2f mm)\n",
        static_cast<long long>(home),
        reached ? "reached the board's limit" : "stopped at an end stop", top_mm, depth.max_mm);
    ctx.out << line;
  }
  std::vector<Change> changes{
      {ck("control.depth_min_mm"), depth.min_mm,
       bus_to_si(BusScale::kPerCount, n, static_cast<double>(home))},
      {ck("control.depth_max_mm"), depth.max_mm, reached ? depth.max_mm : top_mm}};
  return report(ctx, opt, changes, ev);
}

}  // namespace

int run_calibrate(ToolContext& ctx, const CalibrateOptions& opt, std::istream& in) {
  if (ctx.board == nullptr) {
    ctx.err << "planter-can: calibrate needs --board (results are written into it)\n";
    return kExitBadInput;
  }
  OperatorPrompt person(ctx.link, in, ctx.err, opt.ready_after_s);
  if (opt.what == "force") return calibrate_force(ctx, opt, person);
  if (opt.what == "soil-wheel") return calibrate_soil_wheel(ctx, opt, person);
  if (opt.what == "depth") return calibrate_depth(ctx, opt);
  ctx.err << "planter-can: calibrate: '" << opt.what
          << "' is not a calibration (force, soil-wheel, depth)\n";
  return kExitBadInput;
}

}  // namespace planter::cantool
