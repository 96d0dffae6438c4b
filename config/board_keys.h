#pragma once
// The keys of a board file, a machine file and a unit's calibration, declared once
// (config/config_key.h). The loader (config/board_config.cpp) reads through these rows;
// `planterd --list-keys` and docs/configuration.md print them. Where a default lives with the
// loop it configures, the row takes it from there.
#include <cstdint>

#include "config/clamp_ceiling.h"
#include "config/config_key.h"
#include "firmware/controller/controller_config.h"
#include "firmware/controller/setpoint_rules.h"

namespace planter::config {

namespace board_defaults {
inline constexpr ClampLoopConfig kClamp{};
inline constexpr DepthLoopConfig kDepth{};
inline constexpr PlantingMonitorConfig kMonitor{};
inline constexpr GroundFusionConfig kGround{};
inline constexpr ClampCeilingRule kCeiling{};
}  // namespace board_defaults

namespace key_rows {
using enum FileKind;

// clang-format off
inline constexpr ConfigKey kBoardKeys[] = {
  string_key(kBoard, "board", "name", "", "the board's name, shown in logs and recordings", true),
  string_key(kBoard, "board", "toolchain", "native", "the cross toolchain: native, or a file in boards/toolchains/"),
  string_key(kBoard, "board", "machine", "", "the machine this board drives: machines/<name>.toml beside the board or up to two folders above", true),
  string_key(kBoard, "board", "calibration", "", "this unit's calibration, a .toml file beside the board file (unset: none)"),
  string_key(kBoard, "can", "interface", "sim", "the SocketCAN interface (sim: the simulated bus)"),
  integer_key(kBoard, "can", "bitrate", 500000, 10000, 1000000, "bit/s", "the bus's bit rate (checked against the planned bus load)"),
  integer_key(kBoard, "can", "sync_period_ms", 10, 1, 1000, "ms", "the SYNC and control-loop period"),
  integer_key(kBoard, "can", "heartbeat_producer_ms", 100, 10, 10000, "ms", "written to every node's 0x1017 at boot"),
  number_key(kBoard, "can", "heartbeat_consumer_factor", 1.5, 1.1, 3.0, "", "a node is lost after this many heartbeat periods of silence"),
  integer_key(kBoard, "can", "sdo_timeout_ms", 100, 5, 10000, "ms", "how long an SDO answer may take"),
  string_key(kBoard, "gpio", "chip", "sim", "the GPIO chip (sim: simulated lines)"),
  integer_key(kBoard, "gpio", "encoder_a_line", 0, 0, 511, "", "the soil-wheel encoder's channel A"),
  integer_key(kBoard, "gpio", "encoder_b_line", 1, 0, 511, "", "the soil-wheel encoder's channel B"),
  integer_key(kBoard, "gpio", "estop_line", 2, 0, 511, "", "the emergency stop input"),
  integer_key(kBoard, "gpio", "status_line", 3, 0, 511, "", "the status lamp output"),
  bool_key(kBoard, "gpio", "estop_active_low", true, "the e-stop reads low when pressed (a broken wire stops the machine)"),
  integer_key(kBoard, "gpio", "seedling_sensor_line", kNoDefault, 0, 511, "", "the seedling photo-eye where seedlings leave the disc; without it the planting monitor counts nothing", "none"),
  bool_key(kBoard, "gpio", "seedling_sensor_active_low", false, "the photo-eye reads low when the beam is broken"),
  integer_key(kBoard, "gpio", "seedling_sensor_filter_ms", board_defaults::kMonitor.sensor_filter_ns / 1'000'000, 0, 1000, "ms", "beam breaks closer than this are one seedling"),
  integer_key(kBoard, "encoder", "counts_per_rev", 4096, 4, 1 << 24, "", "the soil-wheel encoder's counts per turn after x4 decoding"),
  integer_key(kBoard, "encoder", "glitch_filter_us", 20, 0, 100000, "us", "edges closer than this are noise"),
  integer_key(kBoard, "supervisor", "overrun_threshold_us", 15000, 100, 1000000, "us", "a tick later than this is an overrun"),
  integer_key(kBoard, "supervisor", "overruns_to_fault", 3, 1, 1000, "", "overruns in a row that fault the machine"),
  integer_key(kBoard, "supervisor", "pdo_stale_ms", 100, 10, 10000, "ms", "a PDO older than this is stale (at least two SYNC periods)"),
  integer_key(kBoard, "supervisor", "boot_timeout_ms", 5000, 100, 60000, "ms", "how long the nodes' boot may take"),
  integer_key(kBoard, "realtime", "priority", 80, 0, 99, "", "the loop thread's SCHED_FIFO priority"),
  integer_key(kBoard, "realtime", "cpu", -1, -1, 1023, "", "the CPU the loop is pinned to (-1: not pinned)"),
  bool_key(kBoard, "realtime", "require", false, "refuse to run without real-time scheduling"),
  string_key(kBoard, "gnss", "receiver", "none", "the GNSS receiver: none, sim (the simulator's), or gpsd (a receiver that gpsd serves)"),
  string_key(kBoard, "gnss", "gpsd_host", "127.0.0.1", "where gpsd listens"),
  integer_key(kBoard, "gnss", "gpsd_port", 2947, 1, 65535, "", "gpsd's TCP port (its own default: 2947)"),
  number_key(kBoard, "gnss", "antenna_ahead_m", 0.0, -20.0, 20.0, "m", "the antenna's place ahead of where seedlings leave the disc, along the row"),
  number_key(kBoard, "gnss", "antenna_left_m", 0.0, -20.0, 20.0, "m", "and to the left of it"),
  integer_key(kBoard, "gnss", "min_satellites", board_defaults::kGround.min_satellites, 0, 64, "", "a fix with fewer satellites is not used (assumed)"),
  number_key(kBoard, "gnss", "max_hdop", board_defaults::kGround.max_hdop, 0.5, 99.0, "", "a fix with a larger HDOP is not used (assumed)"),
  number_key(kBoard, "gnss", "slip_walk_per_sqrt_m", board_defaults::kGround.scale_walk_per_sqrt_m, 0.0, 1.0, "1/sqrt(m)", "how fast the wheel's slip may change along the row, 1 sigma (assumed): faster follows the soil, slower averages the receiver's noise"),
  number_key(kBoard, "gnss", "slip_start_sd", board_defaults::kGround.scale_start_sd, 0.001, 0.5, "", "how far the slip may be from the wheel's calibration at the start, 1 sigma (assumed)"),
  number_key(kBoard, "gnss", "apply_beyond_sd", board_defaults::kGround.apply_beyond_sd, 0.0, 5.0, "", "the slip learned moves the distance only by what it holds beyond this many of its SD"),
  integer_key(kBoard, "gnss", "fix_timeout_ms", static_cast<std::int64_t>(board_defaults::kGround.fix_timeout_s * 1000), 100, 900, "ms", "no usable fix for this long: the soil wheel alone, and the alarm"),
  integer_key(kBoard, "console", "port", 0, 0, 65535, "", "the operator console's TCP port (0: no console)"),
  string_key(kBoard, "console", "bind", "0.0.0.0", "the address the console listens on"),
  string_key(kBoard, "console", "viewer_secret", "", "a secret of at least 12 letters or digits that viewing needs (unset: viewing is open)"),
};

inline constexpr ConfigKey kMachineKeys[] = {
  string_key(kMachine, "machine", "name", "", "the machine's name, the same as its file's", true),
  number_key(kMachine, "encoder", "wheel_radius_m", 0.15, 0.02, 1.0, "m", "the soil wheel's nominal radius (the unit's calibration replaces it)"),
  integer_key(kMachine, "encoder", "speed_window_ms", 200, 10, 5000, "ms", "the window the ground speed is measured over"),
  number_key(kMachine, "disc", "radius_m", 0.300, 0.05, 1.0, "m", "the clamping disc's radius at the seedling"),
  number_key(kMachine, "disc", "omega_max_radps", 1.2, 0.1, 20.0, "rad/s", "the disc's top speed"),
  number_key(kMachine, "control", "sigma", 1.5, 0.5, 3.0, "", "the ratio of the disc's rim speed to the ground speed"),
  number_key(kMachine, "control", "sigma_angle_gain_per_s", 3.0, 0.0, 50.0, "1/s", "how fast the disc angle catches up with the ground"),
  number_key(kMachine, "control", "clamp_force_N", 90.0, kClampForceFileRangeN.min, kClampForceFileRangeN.max, "N", "the clamp force set-point (below the ceiling [clamp_ceiling] derives)"),
  retired_key(kMachine, "control", "clamp_ceiling_N", "the clamp's ceiling is derived now, not typed in: from the stems' measured strength and the [clamp_ceiling] table (docs/control.md)"),
  number_key(kMachine, "control", "clamp_kp_mm_per_N", board_defaults::kClamp.kp_mm_per_N, 0.0, 1.0, "mm/N", "the clamp loop's proportional gain"),
  number_key(kMachine, "control", "clamp_ki_mm_per_Ns", board_defaults::kClamp.ki_mm_per_Ns, 0.0, 10.0, "mm/(N s)", "the clamp loop's integral gain"),
  number_key(kMachine, "control", "clamp_model_k_N", board_defaults::kClamp.model_k_N, 0.01, 1e4, "N", "the clamp law's stiffness, for the loop's feed-forward"),
  number_key(kMachine, "control", "clamp_model_x0_mm", board_defaults::kClamp.model_x0_mm, 0.0, 50.0, "mm", "the clamp law's free travel before contact"),
  number_key(kMachine, "control", "clamp_model_n", board_defaults::kClamp.model_n, 1.0, 3.0, "", "the clamp law's exponent"),
  bool_key(kMachine, "control", "clamp_per_stem_grip", board_defaults::kClamp.per_stem_grip, "grip each stem under its own ceiling, read from the nip (false: one set-point for every stem)"),
  number_key(kMachine, "control", "clamp_stem_gain", board_defaults::kClamp.stem.thickness_gain, 0.05, 5.0, "mm/mm", "the lips' added compression per mm of stem over the reference (assumed 0.25-1.0)"),
  number_key(kMachine, "control", "clamp_stem_reference_mm", board_defaults::kClamp.stem.reference_diameter_mm, 1.0, 50.0, "mm", "the stem diameter the clamp law was calibrated with"),
  number_key(kMachine, "control", "clamp_collapse_mm", board_defaults::kClamp.stem.collapse_mm, 0.05, 10.0, "mm", "a drop of the nip's reading between two ticks past this is a stem's wall giving way (damage seen)"),
  retired_key(kMachine, "control", "clamp_stem_step_N", "the stem in the nip is read every tick now (clamp_per_stem_grip, clamp_stem_gain, clamp_collapse_mm)"),
  number_key(kMachine, "control", "clamp_position_max_mm", board_defaults::kClamp.position_max_mm, 1.0, 100.0, "mm", "the roller actuator's travel"),
  number_key(kMachine, "control", "depth_mm", 102.0, kDepthFileRangeMm.min, kDepthFileRangeMm.max, "mm", "the furrow depth set-point"),
  number_key(kMachine, "control", "depth_rate_mm_per_s", 20.0, 1.0, 500.0, "mm/s", "the depth actuator's rate limit"),
  number_key(kMachine, "control", "depth_ki_per_s", board_defaults::kDepth.ki_per_s, 0.0, 20.0, "1/s", "the depth loop's integral gain on the measured depth"),
  number_key(kMachine, "control", "depth_min_mm", board_defaults::kDepth.min_mm, -50.0, 500.0, "mm", "the depth actuator's upper end stop (the unit's calibration replaces it)"),
  number_key(kMachine, "control", "depth_max_mm", board_defaults::kDepth.max_mm, 10.0, 500.0, "mm", "the depth actuator's lower end stop (the unit's calibration replaces it)"),
  number_key(kMachine, "clamp_ceiling", "specimen_length_mm", board_defaults::kCeiling.specimen_length_mm, 5.0, 200.0, "mm", "the strength test's loaded specimen length (assumed 15-50 mm; the paper gives none): the ceiling scales with its inverse"),
  number_key(kMachine, "clamp_ceiling", "stems_past_peak_pct", board_defaults::kCeiling.stems_past_peak_pct, 0.01, 50.0, "%", "the share of reference stems the ceiling lets pass their first peak"),
  number_key(kMachine, "clamp_ceiling", "contact_area_mm2", board_defaults::kCeiling.contact_area_mm2, 10.0, 5000.0, "mm^2", "the lips' contact with a stem: they hold contact area / diameter of it"),
  number_key(kMachine, "clamp_ceiling", "band_mm", board_defaults::kCeiling.band_mm, 1.0, 200.0, "mm", "the band of flexible protrusions: the most of a stem the lips hold"),
  number_key(kMachine, "planting_monitor", "clamp_pitch_mm", board_defaults::kMonitor.clamp_pitch_mm, 5.0, 500.0, "mm", "the clamps' pitch along the disc rim; the target spacing is this over sigma"),
  number_key(kMachine, "planting_monitor", "skip_ratio", board_defaults::kMonitor.skip_ratio, 1.1, 3.0, "", "a spacing over this times the target is a skip (Kachman and Smith 1995)"),
  number_key(kMachine, "planting_monitor", "multiple_ratio", board_defaults::kMonitor.multiple_ratio, 0.1, 0.9, "", "a spacing of at most this times the target is a multiple"),
  integer_key(kMachine, "planting_monitor", "empty_clamps_to_warn", board_defaults::kMonitor.empty_clamps_to_warn, 1, 1000, "", "empty clamps in a row that raise the empty-belt warning"),
  number_key(kMachine, "planting_monitor", "row_spacing_mm", board_defaults::kMonitor.row_spacing_mm, 100.0, 5000.0, "mm", "the rows' spacing, for the population per hectare"),
  number_key(kMachine, "planting_monitor", "spacing_cv_alarm", board_defaults::kMonitor.spacing_cv_alarm, 0.01, 2.0, "", "a spacing CV above this raises the uneven-spacing alarm (assumed)"),
  number_key(kMachine, "planting_monitor", "singulation_alarm_pct", board_defaults::kMonitor.singulation_alarm_pct, 50.0, 100.0, "%", "singulation below this raises the alarm (assumed)"),
  number_key(kMachine, "supervisor", "force_plausible_max_N", 400.0, 10.0, 10000.0, "N", "a clamp force reading above this is a sensor fault"),
  table_key(kMachine, "nodes", "disc_drive", "the disc's drive (CiA 402), required", true),
  table_key(kMachine, "nodes", "roller_actuator", "the clamp roller's actuator (CiA 402), required", true),
  table_key(kMachine, "nodes", "depth_actuator", "the opener's depth actuator (CiA 402), required", true),
  table_key(kMachine, "nodes", "force_sensor", "the clamp's load cell (CiA 404), required", true),
  required_integer_key(kMachine, "nodes.*", "id", 1, 127, "the node's CANopen ID"),
  integer_key(kMachine, "nodes.*", "profile", kNoDefault, 0, 0xFFFF, "", "the node's CiA device profile", "402 (404 for the force sensor)"),
  integer_key(kMachine, "nodes.*", "vendor_id", 0, 0, 0xFFFFFFFF, "", "the identity checked at boot (0x1018:1)"),
  integer_key(kMachine, "nodes.*", "product_code", 0, 0, 0xFFFFFFFF, "", "the identity checked at boot (0x1018:2)"),
  number_key(kMachine, "nodes.*", "counts_per_unit", 1.0, 1e-6, 1e9, "", "the node's counts per SI unit (rad, mm or N)"),
  number_key(kMachine, "nodes.*", "zero_counts", 0.0, -1e9, 1e9, "", "the node's reading at zero (the load cell's tare)"),
  number_key(kMachine, "nodes.*", "rated_torque", 1.0, 1e-6, 1e9, "", "the base of the drive's torque or force object 0x6077"),
  number_key(kMachine, "nodes.*", "profile_velocity", 0.0, 0.0, 1e6, "", "the profile velocity written at boot, in units a second (0: left as is)"),
  strings_key(kMachine, "nodes.*", "tpdo1", "objects the node sends, \"index:sub:bits\""),
  strings_key(kMachine, "nodes.*", "tpdo2", "as tpdo1"),
  strings_key(kMachine, "nodes.*", "tpdo3", "as tpdo1"),
  strings_key(kMachine, "nodes.*", "tpdo4", "as tpdo1"),
  strings_key(kMachine, "nodes.*", "rpdo1", "objects the node receives, \"index:sub:bits\""),
  strings_key(kMachine, "nodes.*", "rpdo2", "as rpdo1"),
  strings_key(kMachine, "nodes.*", "rpdo3", "as rpdo1"),
  strings_key(kMachine, "nodes.*", "rpdo4", "as rpdo1"),
};

inline constexpr ConfigKey kCalibrationKeys[] = {
  number_key(kCalibration, "encoder", "wheel_radius_m", kNoDefault, 0.02, 1.0, "m", "the soil wheel's measured effective radius", "the machine's"),
  number_key(kCalibration, "nodes.force_sensor", "zero_counts", kNoDefault, -1e9, 1e9, "counts", "the load cell's measured tare", "the machine's"),
  number_key(kCalibration, "nodes.force_sensor", "counts_per_unit", kNoDefault, 1e-6, 1e9, "counts/N", "the load cell's measured span, counts per N", "the machine's"),
  number_key(kCalibration, "control", "depth_min_mm", kNoDefault, -50.0, 500.0, "mm", "the depth actuator's measured upper end stop", "the machine's"),
  number_key(kCalibration, "control", "depth_max_mm", kNoDefault, 10.0, 500.0, "mm", "the depth actuator's measured lower end stop", "the machine's"),
};
// clang-format on
}  // namespace key_rows
using key_rows::kBoardKeys;
using key_rows::kCalibrationKeys;
using key_rows::kMachineKeys;

// The three files a board is made of, in the order `planterd --list-keys` prints them.
inline constexpr std::span<const ConfigKey> kBoardFileKeys[] = {kBoardKeys, kMachineKeys,
                                                                kCalibrationKeys};

inline constexpr KeyTables board_key_tables(FileKind here) { return {here, kBoardFileKeys}; }

}  // namespace planter::config
