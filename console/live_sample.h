#pragma once
// One sample of the machine for the console: what the operator sees, in SI units (mm where
// named). Taken from the controller's telemetry in the loop (a plain copy, no allocation) and
// turned into JSON by the server's threads.
#include <cstdint>
#include <limits>
#include <string>

#include "firmware/controller/telemetry.h"
#include "firmware/io/signal_table.h"

namespace planter::console {

struct LiveSample {
  double t_s = 0.0;
  SupervisorState state = SupervisorState::kBoot;
  std::uint32_t faults = 0;
  std::uint32_t warnings = 0;
  double v_mps = 0.0;
  double sigma_seen = 0.0;  // R*omega / v as the controller sees it
  double sigma_true = std::numeric_limits<double>::quiet_NaN();  // where known (simulation)
  double omega_radps = 0.0;
  double clamp_force_N = 0.0;
  double clamp_force_target_N = 0.0;
  double depth_mm = 0.0;
  double depth_target_mm = 0.0;
  PlantingFigures planting;
  // The GNSS receiver, where the board has one: how the fusion uses it, the slip it has
  // learned, and the newest fix's figures.
  bool gnss_fitted = false;
  GnssUse gnss_use = GnssUse::kNone;
  double slip_est = 0.0;
  double v_gnss_mps = 0.0;
  int gnss_mode = 0;
  int satellites = 0;
  double hdop = 0.0;
};

// The console gets ten samples a second (the page polls five times a second): one every this
// many control ticks of period_ns.
constexpr std::int64_t kLiveSamplePeriodNs = 100'000'000;
constexpr std::int64_t ticks_per_live_sample(std::int64_t period_ns) {
  return period_ns >= kLiveSamplePeriodNs ? 1 : kLiveSamplePeriodNs / period_ns;
}

// The console's JSON names its values by their recording columns (docs/recording-format.md), so
// the page, a recording and planter-can show one name for one signal. A name here that is not
// in the signal table does not compile.
consteval std::string_view signal_key(std::string_view column) {
  return known_signal(column).column;
}
// The simulator's truth column (sim/plant/truth_columns.h, above this layer; a test holds the
// two to each other).
inline constexpr const char* kTrueSigmaKey = "true_sigma";

// The sample a tick's telemetry gives (sigma_true left unknown).
LiveSample live_sample(double t_s, const Telemetry& t);
// The sample as one JSON object (NaN as null: the page shows "unknown").
// `recording`: the file the operator's recording goes to, "" when none (the page shows it).
std::string to_json(const LiveSample& s, const std::string& recording = "");

}  // namespace planter::console
