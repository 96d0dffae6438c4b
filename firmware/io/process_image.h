#pragma once
// The process image: what the I/O layer read from the machine this tick, in SI units (mm where
// named), and what the controller commands back. The controller sees only these two structs;
// CANopen, counts and scales stay in the I/O layer (signal_table.h says which object is which).
#include <array>
#include <cstdint>

#include "firmware/sensing/gnss_use.h"
#include "planter/hal/gnss.h"

namespace planter {

struct MachineState {
  // Soil-wheel encoder.
  std::int64_t wheel_counts = 0;
  double distance_m = 0.0;
  double v_wheel_mps = 0.0;
  std::uint32_t encoder_invalid = 0;  // quadrature transitions that skipped a state

  // The GNSS receiver, where the board has one (hal::GnssSource): its newest fix (sequence 0:
  // none yet) and its speed over ground (0 before the first). The antenna's place: the newest
  // fix's while it has one no older than kGnssPlaceMaxAgeNs, else 0, 0 (no place).
  static constexpr std::int64_t kGnssPlaceMaxAgeNs = 1'000'000'000;
  bool gnss_fitted = false;
  bool gnss_connected = false;
  hal::GnssFix gnss;
  double v_gnss_mps = 0.0;
  double lat_deg = 0.0, lon_deg = 0.0;

  // Process values from the nodes' TPDOs.
  double omega_radps = 0.0;
  double disc_angle_rad = 0.0;
  double disc_torque_Nm = 0.0;
  double clamp_pos_mm = 0.0;
  double clamp_force_N = 0.0;
  double depth_mm = 0.0;
  double depth_force_N = 0.0;

  // Seedling photo-eye: the seedlings that broke its beam since the last tick, each at the
  // distance travelled (distance_m's scale) when it did. More than fit are counted as dropped.
  static constexpr std::uint32_t kMaxSeedlingsPerTick = 8;
  std::array<double, kMaxSeedlingsPerTick> seedling_at_m{};
  std::uint32_t seedlings_this_tick = 0;
  std::uint32_t seedlings_dropped = 0;  // since start

  // Lines.
  bool estop = false;

  // The links: the CAN interface itself and the nodes behind it.
  bool link_up = true;               // the interface is up (false while the cable is out)
  std::uint32_t link_downs = 0;      // times the interface went down since start
  bool nodes_started = false;        // commissioning finished and NMT start sent
  bool nodes_ready = false;          // every node operational and every drive enabled
  std::uint32_t link_faults = 0;     // fault:: bits the links saw this tick (heartbeat, EMCY...)
  std::uint32_t unknown_frames = 0;  // frames with an ID no node claims, since start
};

struct MachineCommand {
  double omega_cmd_radps = 0.0;   // disc speed
  double clamp_pos_cmd_mm = 0.0;  // roller position
  double depth_cmd_mm = 0.0;      // opener position
  bool drives_enabled = false;    // CiA 402 operation enabled; false: quick stop
  bool commissioning = false;     // boot the nodes (reset, configure, start) while true
  bool status_lamp = false;

  // What the controller reports with its command (not sent to a node).
  double clamp_force_cmd_N = 0.0;     // the set-point the roller position is trimmed towards
  double clamp_force_target_N = 0.0;  // the operator's clamp force (the ramp's end)
  // What the set-point ramps to for the stem in the nip now: the operator's force, or below it
  // under the stem's own ceiling (ClampLoopConfig::per_stem_grip).
  double clamp_force_aim_N = 0.0;
  double depth_target_mm = 0.0;  // the operator's furrow depth
  double sigma = 0.0;            // R*omega / v as the controller sees it
  // The ground as the sigma loop sees it (firmware/sensing/ground_fusion.h): the wheel's,
  // corrected for the slip GNSS measured where a receiver is fitted.
  double ground_speed_mps = 0.0;
  double slip_est = 0.0;  // the soil wheel's slip beyond its calibration, as estimated
  GnssUse gnss_use = GnssUse::kNone;
};

}  // namespace planter
