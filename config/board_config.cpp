#include "config/board_config.h"

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <set>

#include "config/board_checks.h"
#include "config/board_keys.h"
#include "config/toml_section.h"
#include "firmware/canopen/profile_objects.h"
#include "firmware/controller/setpoint_rules.h"

namespace planter::config {
namespace {

consteval const ConfigKey& bk(std::string_view dotted) { return key_in(kBoardKeys, dotted); }
consteval const ConfigKey& mk(std::string_view dotted) { return key_in(kMachineKeys, dotted); }
consteval const ConfigKey& ck(std::string_view dotted) { return key_in(kCalibrationKeys, dotted); }

// A mapping the node's profile cannot serve is refused here, not at the boot
// (firmware/canopen/profile_objects.h); manufacturer-specific objects are left to the boot.
canopen::PdoMapping parse_pdo(TomlSection& node, const std::string& key, std::uint16_t profile,
                              bool tpdo) {
  canopen::PdoMapping m;
  const auto entries = node.strings(key);
  if (entries.size() > canopen::PdoMapping::kMaxEntries) node.fail(key, "at most 8 entries");
  for (const std::string& text : entries) {
    // "IIII:SS:BB" hex index, hex sub-index, decimal bits.
    unsigned index = 0, sub = 0, bits = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%x:%x:%u%c", &index, &sub, &bits, &tail) != 3 ||
        index > 0xFFFF || sub > 0xFF || (bits != 8 && bits != 16 && bits != 32)) {
      node.fail(key, "entry \"" + text +
                         "\" must be \"index:sub:bits\" (hex index and sub, bits 8, 16 or 32)");
    }
    const canopen::PdoEntry entry{static_cast<std::uint16_t>(index), static_cast<std::uint8_t>(sub),
                                  static_cast<std::uint8_t>(bits)};
    const canopen::MappingVerdict verdict =
        canopen::check_mapping(profile, entry.index, entry.sub, entry.bits, tpdo);
    if (!verdict.served()) {
      const std::string size = verdict.check == canopen::MappingCheck::kSizeDiffers
                                   ? " (" + std::to_string(8 * verdict.object->size) + " bits)"
                                   : std::string();
      node.fail(key, "entry \"" + text + "\": " + canopen::mapping_check_text(verdict.check) +
                         size + " (CiA " + std::to_string(profile) + ")");
    }
    m.entries[m.count++] = entry;
  }
  if (m.total_bits() > 64) node.fail(key, "mapped objects exceed 8 bytes");
  return m;
}

// One unit's measured values (the board's calibration file, `planter-can calibrate`).
struct Calibration {
  std::optional<double> wheel_radius_m;
  std::optional<double> force_zero_counts;
  std::optional<double> force_counts_per_unit;
  std::optional<double> depth_min_mm;
  std::optional<double> depth_max_mm;
};

Calibration read_calibration(const std::string& path) {
  TomlDocument doc(path, board_key_tables(FileKind::kCalibration));
  TomlSection root = doc.root();
  Calibration cal;
  if (auto enc = root.table("encoder")) {
    if (enc->has(ck("encoder.wheel_radius_m")))
      cal.wheel_radius_m = enc->number(ck("encoder.wheel_radius_m"));
    enc->reject_unknown_keys();
  }
  if (auto nodes = root.table("nodes")) {
    if (auto f = nodes->table("force_sensor")) {
      if (f->has(ck("nodes.force_sensor.zero_counts")))
        cal.force_zero_counts = f->number(ck("nodes.force_sensor.zero_counts"));
      if (f->has(ck("nodes.force_sensor.counts_per_unit")))
        cal.force_counts_per_unit = f->number(ck("nodes.force_sensor.counts_per_unit"));
      f->reject_unknown_keys();
    }
    nodes->reject_unknown_keys();
  }
  if (auto ctl = root.table("control")) {
    if (ctl->has(ck("control.depth_min_mm")))
      cal.depth_min_mm = ctl->number(ck("control.depth_min_mm"));
    if (ctl->has(ck("control.depth_max_mm")))
      cal.depth_max_mm = ctl->number(ck("control.depth_max_mm"));
    ctl->reject_unknown_keys();
  }
  root.reject_unknown_keys();
  return cal;
}

// machines/<name>.toml beside the board file or in a folder above it (boards/<b>/ in the
// source tree, /etc/planter/ in the package).
std::string find_machine(const std::string& board_path, TomlSection& board,
                         const std::string& name) {
  if (name.find('/') != std::string::npos || name.find("..") != std::string::npos)
    board.fail(bk("board.machine"), "must be a machine's name (machines/<name>.toml), not a path");
  std::filesystem::path dir = std::filesystem::path(board_path).parent_path();
  if (dir.empty()) dir = ".";
  std::filesystem::path tried;
  for (int up = 0; up < 3; ++up, dir = dir / "..") {
    const std::filesystem::path candidate = dir / "machines" / (name + ".toml");
    if (up == 0) tried = candidate;
    std::error_code ec;
    if (std::filesystem::exists(candidate, ec)) {
      // Resolved as the OS does: ".." after a symlinked folder is the link target's parent.
      const auto resolved = std::filesystem::weakly_canonical(candidate, ec);
      return ec ? candidate.string() : resolved.string();
    }
  }
  board.fail(bk("board.machine"), "no machines/" + name +
                                      ".toml beside the board file or up to two " +
                                      "folders above it (first tried " + tried.string() + ")");
}

void parse_node(TomlSection& nodes, NodeRole role, NodeConfig& out, std::set<int>& ids,
                const ControllerConfig& c, const Calibration& cal) {
  auto t = nodes.table(node_role_name(role));
  if (!t) {
    throw ConfigError(nodes.file(), nodes.line(), nodes.dotted(node_role_name(role)),
                      "node is missing (a table with id, profile and PDO maps)");
  }
  out.role = role;
  out.node_id = static_cast<std::uint8_t>(t->integer(mk("nodes.*.id")));
  if (!ids.insert(out.node_id).second)
    t->fail(mk("nodes.*.id"),
            "node ID " + std::to_string(out.node_id) + " is used by another node");
  const bool sensor = role == NodeRole::kForceSensor;
  out.profile = static_cast<std::uint16_t>(t->integer(mk("nodes.*.profile"), sensor ? 404 : 402));
  if (out.profile != (sensor ? 404 : 402))
    t->fail(mk("nodes.*.profile"),
            sensor ? "must be 404 (measuring device)" : "must be 402 (drive)");
  out.vendor_id = static_cast<std::uint32_t>(t->integer(mk("nodes.*.vendor_id")));
  out.product_code = static_cast<std::uint32_t>(t->integer(mk("nodes.*.product_code")));
  out.counts_per_unit = t->number(mk("nodes.*.counts_per_unit"));
  out.zero_counts = t->number(mk("nodes.*.zero_counts"));
  out.rated_torque = t->number(mk("nodes.*.rated_torque"));
  out.profile_velocity_units_per_s = t->number(mk("nodes.*.profile_velocity"));
  if (sensor && cal.force_zero_counts) out.zero_counts = *cal.force_zero_counts;
  if (sensor && cal.force_counts_per_unit) out.counts_per_unit = *cal.force_counts_per_unit;
  for (int k = 0; k < 4; ++k) {
    out.tpdo[static_cast<std::size_t>(k)] =
        parse_pdo(*t, "tpdo" + std::to_string(k + 1), out.profile, true);
    out.rpdo[static_cast<std::size_t>(k)] =
        parse_pdo(*t, "rpdo" + std::to_string(k + 1), out.profile, false);
  }
  check_node_scaling(*t, out, c);
  t->reject_unknown_keys();
}

// [gnss]: which receiver, where gpsd is, and the fix limits the ground fusion takes.
// [clamp_ceiling]: the ceiling derived at the reference stem (config/clamp_ceiling.h), and the
// set-point below it; `control` holds the set-point.
void read_clamp_ceiling(std::optional<TomlSection> t, std::optional<TomlSection> control,
                        BoardConfig& b) {
  ClampCeilingRule& r = b.clamp_ceiling;
  if (t) {
    r.specimen_length_mm = t->number(mk("clamp_ceiling.specimen_length_mm"));
    r.stems_past_peak_pct = t->number(mk("clamp_ceiling.stems_past_peak_pct"));
    r.contact_area_mm2 = t->number(mk("clamp_ceiling.contact_area_mm2"));
    r.band_mm = t->number(mk("clamp_ceiling.band_mm"));
    t->reject_unknown_keys();
  }
  ClampLoopConfig& clamp = b.controller.clamp;
  clamp.ceiling_N = clamp_ceiling_N(r, clamp.stem.reference_diameter_mm);
  if (clamp.setpoint_N < clamp.ceiling_N) return;
  const std::string why =
      "must be below the " + clamp_ceiling_derivation(r, clamp.stem.reference_diameter_mm);
  if (control) control->fail(mk("control.clamp_force_N"), why);
  throw ConfigError(b.machine_file, 1, std::string(dotted_name(mk("control.clamp_force_N"))), why);
}

void read_gnss(TomlSection& g, BoardConfig& b) {
  GnssBoardConfig& r = b.gnss;
  r.receiver = g.string(bk("gnss.receiver"));
  if (r.receiver != "none" && r.receiver != "sim" && r.receiver != "gpsd")
    g.fail(bk("gnss.receiver"), "must be none, sim or gpsd");
  r.gpsd_host = g.string(bk("gnss.gpsd_host"));
  g.reject_control_characters("gpsd_host", r.gpsd_host);
  r.gpsd_port = static_cast<int>(g.integer(bk("gnss.gpsd_port")));
  r.antenna_ahead_m = g.number(bk("gnss.antenna_ahead_m"));
  r.antenna_left_m = g.number(bk("gnss.antenna_left_m"));
  GroundFusionConfig& f = b.controller.ground;
  f.gnss_fitted = r.receiver != "none";
  f.min_satellites = static_cast<int>(g.integer(bk("gnss.min_satellites")));
  f.max_hdop = g.number(bk("gnss.max_hdop"));
  f.scale_walk_per_sqrt_m = g.number(bk("gnss.slip_walk_per_sqrt_m"));
  f.scale_start_sd = g.number(bk("gnss.slip_start_sd"));
  f.apply_beyond_sd = g.number(bk("gnss.apply_beyond_sd"));
  f.fix_timeout_s = static_cast<double>(g.integer(bk("gnss.fix_timeout_ms"))) * 1e-3;
  f.max_speed_mps = b.controller.supervisor.ground_speed_plausible_max_mps;
  g.reject_unknown_keys();
}

}  // namespace

// [can]; the lines of the bit rate and the SYNC period, for the bus-load and PDO checks' message.
void read_can(TomlSection& can, BoardConfig& b, int& bitrate_line, int& sync_line) {
  ControllerConfig& c = b.controller;
  bitrate_line = can.line_of(std::string(bk("can.bitrate").name));
  sync_line = can.line_of(std::string(bk("can.sync_period_ms").name));
  b.can_interface = can.string(bk("can.interface"));
  c.can.bitrate_bps = static_cast<std::uint32_t>(can.integer(bk("can.bitrate")));
  c.can.sync_period_ns = can.integer(bk("can.sync_period_ms")) * 1'000'000;
  c.can.heartbeat_producer_ms =
      static_cast<std::uint16_t>(can.integer(bk("can.heartbeat_producer_ms")));
  c.can.heartbeat_consumer_factor = can.number(bk("can.heartbeat_consumer_factor"));
  c.can.sdo_timeout_ns = can.integer(bk("can.sdo_timeout_ms")) * 1'000'000;
  can.reject_unknown_keys();
}

// [gpio]: the board's lines, each doing one job.
void read_gpio(TomlSection& gpio, BoardConfig& b) {
  ControllerConfig& c = b.controller;
  b.gpio.chip = gpio.string(bk("gpio.chip"));
  b.gpio.encoder_a = static_cast<int>(gpio.integer(bk("gpio.encoder_a_line")));
  b.gpio.encoder_b = static_cast<int>(gpio.integer(bk("gpio.encoder_b_line")));
  b.gpio.estop = static_cast<int>(gpio.integer(bk("gpio.estop_line")));
  b.gpio.status = static_cast<int>(gpio.integer(bk("gpio.status_line")));
  c.estop_active_low = gpio.boolean(bk("gpio.estop_active_low"));
  // The seedling photo-eye is optional: without it the planting monitor has nothing to count.
  if (gpio.has(bk("gpio.seedling_sensor_line"))) {
    b.gpio.seedling_sensor = static_cast<int>(gpio.integer(bk("gpio.seedling_sensor_line")));
    b.gpio.seedling_sensor_active_low = gpio.boolean(bk("gpio.seedling_sensor_active_low"));
    c.monitor.sensor_fitted = true;
    c.monitor.sensor_filter_ns = gpio.integer(bk("gpio.seedling_sensor_filter_ms")) * 1'000'000;
  }
  // Each line does one job: name the key that reuses an earlier one.
  const std::pair<const ConfigKey*, int> lines[] = {
      {&bk("gpio.encoder_a_line"), b.gpio.encoder_a},
      {&bk("gpio.encoder_b_line"), b.gpio.encoder_b},
      {&bk("gpio.estop_line"), b.gpio.estop},
      {&bk("gpio.status_line"), b.gpio.status},
      {&bk("gpio.seedling_sensor_line"), b.gpio.seedling_sensor}};
  for (std::size_t i = 1; i < std::size(lines); ++i) {
    for (std::size_t k = 0; k < i; ++k) {
      if (lines[i].second >= 0 && lines[i].second == lines[k].second)
        gpio.fail(*lines[i].first,
                  "line " + std::to_string(lines[i].second) + " is already " +
                      std::string(lines[k].first->name) +
                      " (encoder A, encoder B, e-stop, status and the seedling photo-eye need "
                      "a line each)");
    }
  }
  gpio.reject_unknown_keys();
}

// [control]: the loops' set-points, gains and laws; the depth's end stops may be the unit's.
void read_control(TomlSection& ctl, const Calibration& cal, BoardConfig& b) {
  ControllerConfig& c = b.controller;
  c.sigma.sigma = ctl.number(mk("control.sigma"));
  c.sigma.angle_gain_per_s = ctl.number(mk("control.sigma_angle_gain_per_s"));
  c.clamp.setpoint_N = ctl.number(mk("control.clamp_force_N"));
  c.clamp.kp_mm_per_N = ctl.number(mk("control.clamp_kp_mm_per_N"));
  c.clamp.ki_mm_per_Ns = ctl.number(mk("control.clamp_ki_mm_per_Ns"));
  c.clamp.model_k_N = ctl.number(mk("control.clamp_model_k_N"));
  c.clamp.model_x0_mm = ctl.number(mk("control.clamp_model_x0_mm"));
  c.clamp.model_n = ctl.number(mk("control.clamp_model_n"));
  c.clamp.position_max_mm = ctl.number(mk("control.clamp_position_max_mm"));
  c.clamp.per_stem_grip = ctl.boolean(mk("control.clamp_per_stem_grip"));
  c.clamp.stem.thickness_gain = ctl.number(mk("control.clamp_stem_gain"));
  c.clamp.stem.reference_diameter_mm = ctl.number(mk("control.clamp_stem_reference_mm"));
  c.clamp.stem.collapse_mm = ctl.number(mk("control.clamp_collapse_mm"));
  c.depth.target_mm = ctl.number(mk("control.depth_mm"));
  c.depth.rate_mm_per_s = ctl.number(mk("control.depth_rate_mm_per_s"));
  c.depth.ki_per_s = ctl.number(mk("control.depth_ki_per_s"));
  c.depth.min_mm = ctl.number(mk("control.depth_min_mm"));
  c.depth.max_mm = ctl.number(mk("control.depth_max_mm"));
  if (cal.depth_min_mm) c.depth.min_mm = *cal.depth_min_mm;
  if (cal.depth_max_mm) c.depth.max_mm = *cal.depth_max_mm;
  const std::string from_cal =
      cal.depth_min_mm || cal.depth_max_mm ? " (end stops from " + b.calibration_file + ")" : "";
  if (c.depth.max_mm <= c.depth.min_mm)
    ctl.fail(mk("control.depth_max_mm"), "must be above depth_min_mm" + from_cal);
  if (c.depth.target_mm > c.depth.max_mm)
    ctl.fail(mk("control.depth_mm"),
             "must not be beyond depth_max_mm (the actuator's travel)" + from_cal);
  ctl.reject_unknown_keys();
}

// [planting_monitor]: the clamp pitch is the machine's; the skip and multiple limits follow
// Kachman and Smith (1995) unless the machine file says otherwise.
void read_monitor(TomlSection& mon, ControllerConfig& c) {
  c.monitor.clamp_pitch_mm = mon.number(mk("planting_monitor.clamp_pitch_mm"));
  c.monitor.skip_ratio = mon.number(mk("planting_monitor.skip_ratio"));
  c.monitor.multiple_ratio = mon.number(mk("planting_monitor.multiple_ratio"));
  c.monitor.empty_clamps_to_warn =
      static_cast<std::uint32_t>(mon.integer(mk("planting_monitor.empty_clamps_to_warn")));
  c.monitor.row_spacing_mm = mon.number(mk("planting_monitor.row_spacing_mm"));
  c.monitor.spacing_cv_alarm = mon.number(mk("planting_monitor.spacing_cv_alarm"));
  c.monitor.singulation_alarm_pct = mon.number(mk("planting_monitor.singulation_alarm_pct"));
  mon.reject_unknown_keys();
}

// [console]: where the operator's console listens, and the viewers' secret.
void read_console(TomlSection& con, BoardConfig& b) {
  b.console.port = static_cast<int>(con.integer(bk("console.port")));
  b.console.bind = con.string(bk("console.bind"));
  con.reject_control_characters("bind", b.console.bind);
  b.console.viewer_secret = con.string(bk("console.viewer_secret"));
  std::size_t letters = 0;
  for (char ch : b.console.viewer_secret)
    letters += std::isalnum(static_cast<unsigned char>(ch)) ? 1 : 0;
  if (!b.console.viewer_secret.empty() && letters < 12)
    con.fail(bk("console.viewer_secret"),
             "needs at least 12 letters or digits (leave it out: viewing is open)");
  con.reject_unknown_keys();
}

// The unit's calibration the board names (a .toml file beside it), or `override` instead.
Calibration read_named_calibration(TomlSection& board, const std::string& path,
                                   const std::string& override, BoardConfig& b) {
  const std::string calibration = board.string(bk("board.calibration"));
  if (calibration.empty()) return {};
  const bool toml_name =
      calibration.size() > 5 && calibration.compare(calibration.size() - 5, 5, ".toml") == 0;
  if (calibration.find('/') != std::string::npos || !toml_name)
    board.fail(bk("board.calibration"), "must be the name of a .toml file beside the board file");
  b.calibration_file = (std::filesystem::path(path).parent_path() / calibration).string();
  std::error_code ec;
  if (override.empty() && !std::filesystem::exists(b.calibration_file, ec)) {
    board.fail(bk("board.calibration"),
               b.calibration_file +
                   ": no such file (the unit's calibration; planter-can "
                   "calibrate writes its values, the package installs one)");
  }
  return read_calibration(override.empty() ? b.calibration_file : override);
}

// [encoder]: the counts and the glitch filter are the board's (its encoder and lines); the
// wheel radius and the speed window are the machine's, the radius calibrated per unit.
void read_encoder(std::optional<TomlSection> board_enc, std::optional<TomlSection> machine_enc,
                  const Calibration& cal, ControllerConfig& c) {
  if (board_enc) {
    c.encoder.counts_per_rev =
        static_cast<std::uint32_t>(board_enc->integer(bk("encoder.counts_per_rev")));
    c.encoder.glitch_filter_ns = board_enc->integer(bk("encoder.glitch_filter_us")) * 1000;
  }
  if (machine_enc) {
    c.encoder.wheel_radius_m = machine_enc->number(mk("encoder.wheel_radius_m"));
    c.encoder.speed_window_ns = machine_enc->integer(mk("encoder.speed_window_ms")) * 1'000'000;
  }
  if (cal.wheel_radius_m) c.encoder.wheel_radius_m = *cal.wheel_radius_m;
  if (board_enc) board_enc->reject_unknown_keys();
  if (machine_enc) machine_enc->reject_unknown_keys();
}

// [supervisor]: the loop's timing is the board's; the plausibility limits are the machine's.
void read_supervisor(std::optional<TomlSection> board_sup, std::optional<TomlSection> machine_sup,
                     ControllerConfig& c) {
  if (board_sup) {
    c.supervisor.overrun_threshold_ns =
        board_sup->integer(bk("supervisor.overrun_threshold_us")) * 1000;
    c.supervisor.overruns_to_fault =
        static_cast<std::uint32_t>(board_sup->integer(bk("supervisor.overruns_to_fault")));
    c.supervisor.pdo_stale_ns = board_sup->integer(bk("supervisor.pdo_stale_ms")) * 1'000'000;
    c.supervisor.boot_timeout_ns = board_sup->integer(bk("supervisor.boot_timeout_ms")) * 1'000'000;
  }
  if (machine_sup) {
    c.supervisor.force_plausible_max_N =
        machine_sup->number(mk("supervisor.force_plausible_max_N"));
  }
  if (board_sup) board_sup->reject_unknown_keys();
  if (machine_sup) machine_sup->reject_unknown_keys();
}

// [machine]: the machine file names the machine the board asked for.
void check_machine_name(TomlSection& mroot, const std::string& machine, BoardConfig& b) {
  auto m = mroot.table("machine");
  if (!m) throw ConfigError(b.machine_file, 1, "machine", "table is missing (name)");
  b.machine_name = m->string(mk("machine.name"));
  if (b.machine_name != machine)
    m->fail(mk("machine.name"),
            "is \"" + b.machine_name + "\" but the file is named for \"" + machine + "\"");
  m->reject_unknown_keys();
}

// CiA 301 leaves the bus's budget to the integrator; above 100 % frames queue without bound,
// and above half the bus a retransmission or a spare node's traffic already delays the PDOs.
void check_bus_load(const std::string& path, int bitrate_line, BoardConfig& b) {
  const ControllerConfig& c = b.controller;
  b.planned_bus_load_pct = planned_bus_load_pct(c);
  char load[200];
  std::snprintf(load, sizeof load,
                "the board's SYNC, PDOs and heartbeats need %.0f %% of %u bit/s every %.1f ms",
                b.planned_bus_load_pct, c.can.bitrate_bps,
                static_cast<double>(c.can.sync_period_ns) * 1e-6);
  if (b.planned_bus_load_pct > 100.0) {
    throw ConfigError(
        path, bitrate_line, dotted_name(bk("can.bitrate")),
        std::string(load) + "; at most 100 % (raise the bit rate or the SYNC period)");
  }
  if (b.planned_bus_load_pct > 50.0) {
    b.warnings.push_back(path + ": " + load + " (over the 50 % guideline)");
  }
}

BoardConfig load_board(const std::string& path, const std::string& calibration_override) {
  TomlDocument doc(path, board_key_tables(FileKind::kBoard));
  TomlSection root = doc.root();
  BoardConfig b;
  b.file = path;
  ControllerConfig& c = b.controller;

  auto board = root.table("board");
  if (!board) throw ConfigError(path, 1, "board", "table is missing (name, toolchain, machine)");
  b.name = board->string(bk("board.name"));
  if (b.name.empty()) board->fail(bk("board.name"), "must not be empty");
  b.toolchain = board->string(bk("board.toolchain"));
  if (!board->has(bk("board.machine")) || board->string(bk("board.machine")).empty())
    board->fail(bk("board.machine"),
                "is required: a board names its machine (machines/<name>.toml beside the board "
                "or up to two folders above it). A board file that holds the machine's sections "
                "itself, the format from before boards and machines were split, is no longer "
                "read: move its [disc], [control], [planting_monitor], [nodes.*] and the "
                "machine's keys of [encoder] and [supervisor] into machines/<name>.toml "
                "(docs/boards.md)");
  const std::string machine = board->string(bk("board.machine"));
  const Calibration cal = read_named_calibration(*board, path, calibration_override, b);
  // The machine's sections come from machines/<machine>.toml.
  b.machine_file = find_machine(path, *board, machine);
  TomlDocument machine_doc(b.machine_file, board_key_tables(FileKind::kMachine));
  TomlSection machine_root = machine_doc.root();
  TomlSection* mroot = &machine_root;
  check_machine_name(*mroot, machine, b);
  board->reject_unknown_keys();
  int bitrate_line = 1, sync_line = 1;
  if (auto can = root.table("can")) read_can(*can, b, bitrate_line, sync_line);
  if (auto gpio = root.table("gpio")) read_gpio(*gpio, b);
  read_encoder(root.table("encoder"), mroot->table("encoder"), cal, c);
  if (auto disc = mroot->table("disc")) {
    c.sigma.disc_radius_m = disc->number(mk("disc.radius_m"));
    c.sigma.omega_max_radps = disc->number(mk("disc.omega_max_radps"));
    disc->reject_unknown_keys();
  }
  if (auto ctl = mroot->table("control")) read_control(*ctl, cal, b);
  read_clamp_ceiling(mroot->table("clamp_ceiling"), mroot->table("control"), b);
  if (auto mon = mroot->table("planting_monitor")) read_monitor(*mon, c);
  c.monitor.target_spacing_mm = c.monitor.clamp_pitch_mm / c.sigma.sigma;
  // One clamp pitch at the rim: the unit of the disc's most lag and of the alarms' carry.
  c.sigma.clamp_pitch_rad = c.monitor.clamp_pitch_mm / 1000.0 / c.sigma.disc_radius_m;
  c.alarms.clamp_pitch_rad = c.sigma.clamp_pitch_rad;
  read_supervisor(root.table("supervisor"), mroot->table("supervisor"), c);
  // A PDO arrives once a SYNC period: one staler than that is every PDO (issue 28, item 12: a
  // 1000 ms SYNC against the 100 ms default passed and faulted the boot's first check).
  if (c.supervisor.pdo_stale_ns < 2 * c.can.sync_period_ns)
    throw ConfigError(path, sync_line, dotted_name(bk("can.sync_period_ms")),
                      std::to_string(c.can.sync_period_ns / 1'000'000) +
                          " ms: the supervisor calls a PDO stale after " +
                          std::to_string(c.supervisor.pdo_stale_ns / 1'000'000) +
                          " ms ([supervisor] pdo_stale_ms), which must be at least two SYNC "
                          "periods, or every PDO is stale");
  if (auto rt = root.table("realtime")) {
    b.realtime.priority = static_cast<int>(rt->integer(bk("realtime.priority")));
    b.realtime.cpu = static_cast<int>(rt->integer(bk("realtime.cpu")));
    b.realtime.require = rt->boolean(bk("realtime.require"));
    rt->reject_unknown_keys();
  }
  if (auto g = root.table("gnss")) read_gnss(*g, b);
  if (auto con = root.table("console")) read_console(*con, b);
  auto nodes = mroot->table("nodes");
  if (!nodes)
    throw ConfigError(
        b.machine_file, 1, "nodes",
        "table is missing (disc_drive, roller_actuator, depth_actuator, force_sensor)");
  std::set<int> ids;
  for (std::size_t i = 0; i < kNodeCount; ++i)
    parse_node(*nodes, static_cast<NodeRole>(i), c.nodes[i], ids, c, cal);
  nodes->reject_unknown_keys();
  root.reject_unknown_keys();
  mroot->reject_unknown_keys();
  check_bus_load(path, bitrate_line, b);
  return b;
}

std::vector<std::string> source_files(const BoardConfig& b) {
  std::vector<std::string> files{b.file};
  if (!b.machine_file.empty()) files.push_back(b.machine_file);
  if (!b.calibration_file.empty()) files.push_back(b.calibration_file);
  return files;
}

}  // namespace planter::config
