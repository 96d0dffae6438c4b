// planter-can: the CAN bus commissioning tool. `planter-can --iface IFACE [--board B] COMMAND`;
// IFACE is a SocketCAN interface or `sim`, the simulated machine in-process.
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "apps/planter-can/cmd_calibrate.h"
#include "apps/planter-can/cmd_check.h"
#include "apps/planter-can/cmd_configure.h"
#include "apps/planter-can/cmd_gnss.h"
#include "apps/planter-can/cmd_info.h"
#include "apps/planter-can/cmd_lss.h"
#include "apps/planter-can/cmd_scan.h"
#include "apps/planter-can/cmd_sdo.h"
#include "apps/planter-can/cmd_traffic.h"
#include "apps/planter-can/sim_link.h"
#include "apps/planter-can/socket_link.h"
#include "apps/version/cli_errors.h"
#include "apps/version/version.h"
#include "config/cli_range.h"
#include "config/config_error.h"
#include "config/durable_file.h"
#include "hal/linux/hal_error.h"
#include "sim/runner/scenario.h"

namespace {

using namespace planter;
using namespace planter::cantool;

std::atomic<bool> g_stop{false};  // set by SIGINT/SIGTERM: monitor, record, replay end cleanly

void on_signal(int) { g_stop.store(true); }

int fail(int code, const std::string& message) {
  std::cerr << "planter-can: " << message << "\n";
  return code;
}

// Every option the command line may hold, and each subcommand, as CLI11 fills them.
struct Cli {
  std::string iface, board_path, scenario_path, session_log;
  bool json = false, no_progress = false, sim_controller = false, no_sim_controller = false;
  int timeout_ms = 100;
  double push_m = 5.0;
  CLI::App *scan = nullptr, *info = nullptr, *sdo = nullptr, *nmt = nullptr, *lss = nullptr,
           *configure = nullptr, *monitor = nullptr, *record = nullptr, *replay = nullptr,
           *decode = nullptr, *calibrate = nullptr, *gnss = nullptr, *check = nullptr;
  ScanOptions scan_options;
  int listen_ms = 300;
  bool no_probe = false;
  std::string info_node;
  std::vector<std::string> sdo_words;
  std::string sdo_file;
  std::string nmt_command, nmt_node;
  LssOptions lss_options;
  std::vector<std::string> lss_identity;
  int lss_timeout_ms = 20;
  ConfigureOptions configure_options;
  bool no_store = false;
  TrafficOptions traffic;
  std::string record_path, replay_path, decode_log, decode_out;
  CalibrateOptions calibrate_options;
  bool no_write = false, write_sim = false;
  CheckOptions check_options;
  double check_listen_s = 2.0;
  bool skip_encoder = false;
  GnssOptions gnss_options;
};

void add_global_options(CLI::App& app, Cli& o) {
  app.add_option("--iface", o.iface, "SocketCAN interface (can0, vcan0) or 'sim'");
  app.add_option("--board", o.board_path, "board file (boards/<board>/board.toml)");
  app.add_flag("--json", o.json, "machine-readable output");
  app.add_option("--timeout-ms", o.timeout_ms, "SDO timeout")
      ->check(planter::config::finite_range(1, 60000));
  app.add_flag("--no-progress", o.no_progress, "no progress line on stderr");
  app.add_option("--sim-scenario", o.scenario_path, "sim: the machine and field to simulate");
  app.add_flag("--sim-controller", o.sim_controller,
               "sim: planterd runs on the bus too (SYNC, PDOs, heartbeats); the default but for "
               "configure, calibrate, lss and replay, done with planterd stopped");
  app.add_flag("--no-sim-controller", o.no_sim_controller,
               "sim: no planterd on the bus (a machine just powered, its nodes pre-operational)");
  app.add_option("--record", o.session_log,
                 "log the whole session (every frame seen and sent) to this candump -L file");
  app.add_option("--sim-push-m", o.push_m, "sim: how far the fixture pushes the machine")
      ->check(planter::config::finite_range(0.1, 1000.0));
}

// The nodes, one by one: scan, info, sdo, nmt, lss, configure.
void add_node_commands(CLI::App& app, Cli& o) {
  o.scan = app.add_subcommand("scan", "list the nodes: listen, then probe IDs 1-127");
  o.scan->add_option("--listen-ms", o.listen_ms, "passive listening first")
      ->check(planter::config::finite_range(0, 60000));
  o.scan->add_flag("--passive", o.no_probe, "listen only, send nothing");

  o.info = app.add_subcommand("info", "identity, versions, errors, heartbeat, PDOs of a node");
  o.info->add_option("node", o.info_node, "node-ID or board role")->required();

  o.sdo = app.add_subcommand("sdo", "CiA 309-3: NODE r IDX SUB [TYPE] | NODE w IDX SUB TYPE VALUE");
  o.sdo->add_option("command", o.sdo_words, "one command line");
  o.sdo->add_option("-f,--file", o.sdo_file, "batch file, one command per line");
  o.sdo->allow_extras(false);
  o.sdo->prefix_command();

  o.nmt = app.add_subcommand("nmt", "start | stop | preop | reset | reset-comm NODE|all");
  o.nmt->add_option("command", o.nmt_command)->required();
  o.nmt->add_option("node", o.nmt_node)->required();

  o.lss = app.add_subcommand("lss", "fastscan | assign NEW_ID | inquire (CiA 305)");
  o.lss->add_option("action", o.lss_options.action)->required();
  o.lss->add_option("new_id", o.lss_options.new_id, "assign: the node-ID to give");
  o.lss
      ->add_option("--identity", o.lss_identity,
                   "VENDOR PRODUCT REVISION SERIAL instead of a fastscan")
      ->expected(4);
  o.lss->add_option("--lss-timeout-ms", o.lss_timeout_ms, "silence this long means no")
      ->check(planter::config::finite_range(1, 10000));

  o.configure =
      app.add_subcommand("configure", "apply the board's node configuration, verify, store");
  o.configure->add_option("--node", o.configure_options.node, "only this node (ID or role)");
  o.configure->add_flag("--dry-run", o.configure_options.dry_run,
                        "print the SDO writes (CiA 309-3 lines)");
  o.configure->add_flag("--no-store", o.no_store, "do not store (0x1010) after verifying");
}

// The bus's traffic: monitor, record, replay, decode.
void add_traffic_commands(CLI::App& app, Cli& o) {
  o.traffic.stop = &g_stop;
  o.monitor = app.add_subcommand("monitor", "live decode with names, units and rates");
  o.monitor->add_option("--duration", o.traffic.duration_s, "seconds (default: until Ctrl-C)")
      ->check(planter::config::finite_range(0.0, 1e7));
  o.monitor->add_flag("--raw", o.traffic.raw, "raw bytes beside the decode");
  o.monitor->add_flag("--summary-only", o.traffic.summary_only, "the rate table only");
  o.monitor->add_option("--summary-every", o.traffic.summary_every_s, "rate table every N seconds")
      ->check(planter::config::finite_range(0.0, 3600.0));

  o.record = app.add_subcommand("record", "candump -L log of the bus, own frames included");
  o.record->add_option("file", o.record_path)->required();
  o.record->add_option("--duration", o.traffic.duration_s, "seconds (default: until Ctrl-C)")
      ->check(planter::config::finite_range(0.0, 1e7));

  o.replay = app.add_subcommand("replay", "send a candump log back onto the bus, timed");
  o.replay->add_option("file", o.replay_path)->required();
  o.replay
      ->add_option("--max-gap", o.traffic.max_gap_s, "silences longer than this (s) are shortened")
      ->capture_default_str()
      ->check(planter::config::finite_range(0.001, 3600.0));
  o.replay->add_option("--speed", o.traffic.speed, "time factor (2 = twice as fast)")
      ->check(planter::config::finite_range(0.001, 1000.0));

  o.decode =
      app.add_subcommand("decode", "candump log -> recording CSV (docs/recording-format.md)");
  o.decode->add_option("log", o.decode_log)->required();
  o.decode->add_option("-o,--out", o.decode_out, "CSV file (default: stdout)");
}

// Commissioning the machine: calibrate, gnss, check.
void add_commissioning_commands(CLI::App& app, Cli& o) {
  CalibrateOptions& cal = o.calibrate_options;
  o.calibrate = app.add_subcommand(
      "calibrate", "force | soil-wheel | depth; results into the unit's calibration file");
  o.calibrate->add_option("what", cal.what)->required();
  o.calibrate->add_flag("--write-sim", o.write_sim,
                        "on --iface sim, write the result into --board's files too (a scratch "
                        "copy)");
  o.calibrate->add_option("--known-N", cal.known_N, "force: the weight, in newtons")
      ->check(planter::config::finite_range(0.001, 1e5));
  o.calibrate->add_option("--distance-m", cal.distance_m, "soil-wheel: the measured distance")
      ->check(planter::config::finite_range(0.01, 1e4));
  o.calibrate->add_option("--samples", cal.samples, "force: readings per step")
      ->check(planter::config::finite_range(1, 10000));
  o.calibrate
      ->add_option("--ready-after-s", cal.ready_after_s,
                   "scripts: wait this long instead of asking for Enter")
      ->check(planter::config::finite_range(0.0, 3600.0));
  o.calibrate->add_flag("--no-write", o.no_write,
                        "show the result, leave the calibration file alone");

  GnssOptions& gnss = o.gnss_options;
  gnss.stop = &g_stop;
  o.gnss = app.add_subcommand(
      "gnss", "the GNSS receiver through gpsd: each fix and whether it is used (no bus)");
  o.gnss->add_option("--host", gnss.host, "gpsd's host (default: the board's, else 127.0.0.1)");
  o.gnss->add_option("--port", gnss.port, "gpsd's port (default: the board's, else 2947)")
      ->check(planter::config::finite_range(1, 65535));
  o.gnss->add_option("--duration", gnss.duration_s, "seconds to watch (default 10)")
      ->check(planter::config::finite_range(0.1, 86400.0));
  o.gnss->add_option("--log", gnss.log_path,
                     "check this NMEA log instead (checksums, time, speed)");

  CheckOptions& check = o.check_options;
  o.check = app.add_subcommand("check", "the commissioning checklist; exit 1 on any fail");
  o.check->add_option("--listen-s", o.check_listen_s, "how long to watch the bus")
      ->check(planter::config::finite_range(0.1, 600.0));
  o.check->add_option("--max-bus-load", check.max_bus_load_pct, "percent")
      ->check(planter::config::finite_range(1.0, 100.0));
  o.check->add_flag("--skip-encoder", o.skip_encoder, "do not check the encoder direction");
  o.check->add_option("--mark-commissioned", check.mark_commissioned,
                      "when every item passes, write this stamp (planterd --commissioned-stamp)");
  o.check
      ->add_option("--ready-after-s", check.ready_after_s,
                   "scripts: wait instead of asking for Enter")
      ->check(planter::config::finite_range(0.0, 3600.0));
}

// On sim with neither a board nor a scenario: the host-sim board, where the package installs it
// or in this build's source tree.
void default_sim_board(Cli& o) {
  if (o.iface != "sim" || !o.board_path.empty() || !o.scenario_path.empty()) return;
  for (const std::string& candidate :
       {std::string("/etc/planter/boards/host-sim/board.toml"),
        std::string(PLANTER_SOURCE_DIR) + "/boards/host-sim/board.toml"}) {
    std::error_code ec;
    if (std::filesystem::exists(candidate, ec)) {
      o.board_path = candidate;
      std::cerr << "planter-can: --iface sim with no --board: the host-sim board (" << candidate
                << ")\n";
      return;
    }
  }
}

// The simulated machine's link: planterd on its bus as on the machine, except for what is done
// with it stopped. Fills `error` and returns null on a refusal.
std::unique_ptr<ToolLink> open_sim_link(const Cli& o, config::BoardConfig& board, bool have_board,
                                        std::string& error) {
  sim::Scenario scenario;
  if (!o.scenario_path.empty()) scenario = sim::load_scenario(o.scenario_path);
  if (have_board) {
    scenario.board = board;
  } else if (o.scenario_path.empty()) {
    error =
        "--iface sim needs --board or --sim-scenario (the simulated machine is built from it); "
        "no host-sim board at /etc/planter/boards/host-sim/board.toml or " PLANTER_SOURCE_DIR
        "/boards/host-sim/board.toml";
    return nullptr;
  } else {
    board = scenario.board;
  }
  SimLinkOptions so;
  const bool planterd_stopped =
      o.configure->parsed() || o.calibrate->parsed() || o.lss->parsed() || o.replay->parsed();
  if (o.sim_controller && o.no_sim_controller) {
    error = "--sim-controller and --no-sim-controller: give one";
    return nullptr;
  }
  so.with_controller = o.sim_controller || (!o.no_sim_controller && !planterd_stopped);
  if (o.calibrate->parsed() && so.with_controller) {
    error =
        "calibrate needs the machine to itself: planterd must be stopped (leave out "
        "--sim-controller)";
    return nullptr;
  }
  const double measured_m = o.calibrate_options.distance_m;
  so.push_distance_m = o.calibrate->parsed() && measured_m > 0 ? measured_m : o.push_m;
  return std::make_unique<SimLink>(scenario, so);
}

// A SocketCAN interface; the encoder lines are opened only by the commands that need them
// (planterd may hold them).
std::unique_ptr<ToolLink> open_socket_link(const Cli& o, const config::BoardConfig& board,
                                           bool have_board) {
  auto socket = std::make_unique<SocketLink>(o.iface);
  const bool wants_encoder = (o.calibrate->parsed() && o.calibrate_options.what == "soil-wheel") ||
                             (o.check->parsed() && !o.skip_encoder);
  if (wants_encoder && have_board && board.gpio.chip != "sim") socket->open_encoder(board);
  return socket;
}

int run_sdo_command(Cli& o, ToolContext& ctx) {
  std::vector<SdoLine> lines;
  if (!o.sdo_file.empty()) {
    std::string error;
    if (!read_batch_file(o.sdo_file, lines, error)) return fail(kExitBadInput, error);
  }
  if (!o.sdo_words.empty()) {
    std::string text;
    for (const auto& w : o.sdo_words) text += (text.empty() ? "" : " ") + w;
    lines.push_back({"command line", text});
  }
  if (lines.empty())
    return fail(kExitBadInput, "sdo: give a command (NODE r IDX SUB [TYPE]) or -f FILE");
  return run_sdo(ctx, lines);
}

int run_lss_command(Cli& o, ToolContext& ctx) {
  if (!o.lss_identity.empty()) {
    std::array<std::uint32_t, 4> id{};
    for (std::size_t i = 0; i < 4; ++i) {
      const auto v = parse_integer(o.lss_identity[i]);
      if (!v || *v < 0 || *v > 0xFFFFFFFF)
        return fail(kExitBadInput,
                    "lss: --identity value '" + o.lss_identity[i] + "' is not a 32-bit number");
      id[i] = static_cast<std::uint32_t>(*v);
    }
    o.lss_options.identity = id;
  }
  o.lss_options.timeout_ns = std::int64_t{o.lss_timeout_ms} * 1'000'000;
  return run_lss(ctx, o.lss_options);
}

int run_calibrate_command(Cli& o, ToolContext& ctx) {
  CalibrateOptions& cal = o.calibrate_options;
  cal.write = !o.no_write;
  // A simulated machine's calibration is no machine's, and the sim's board file is usually
  // the project's own: nothing is written unless asked for (issue 29, the first hour).
  if (o.iface == "sim" && cal.write && !o.write_sim) {
    cal.write = false;
    cal.not_written_because = "a simulated machine: --write-sim writes";
    std::cerr << "planter-can: calibrate on --iface sim: the result is shown, not written into "
              << o.board_path
              << " (give --write-sim, with --board a copy of the board, to write it)\n";
  }
  return run_calibrate(ctx, cal, std::cin);
}

// The subcommand given, on the bus.
int run_command(Cli& o, ToolContext& ctx) {
  if (o.scan->parsed()) {
    o.scan_options.listen_ns = std::int64_t{o.listen_ms} * 1'000'000;
    o.scan_options.probe = !o.no_probe;
    return run_scan(ctx, o.scan_options);
  }
  if (o.info->parsed()) return run_info(ctx, o.info_node);
  if (o.sdo->parsed()) return run_sdo_command(o, ctx);
  if (o.nmt->parsed()) return run_nmt(ctx, o.nmt_command, o.nmt_node);
  if (o.lss->parsed()) return run_lss_command(o, ctx);
  if (o.configure->parsed()) {
    o.configure_options.store = !o.no_store;
    return run_configure(ctx, o.configure_options);
  }
  if (o.monitor->parsed()) return run_monitor(ctx, o.traffic);
  if (o.record->parsed()) return run_record(ctx, o.record_path, o.traffic);
  if (o.replay->parsed()) return run_replay(ctx, o.replay_path, o.traffic);
  if (o.calibrate->parsed()) return run_calibrate_command(o, ctx);
  if (o.check->parsed()) {
    o.check_options.listen_ns = static_cast<std::int64_t>(o.check_listen_s * 1e9);
    o.check_options.encoder = !o.skip_encoder;
    return run_check(ctx, o.check_options, std::cin);
  }
  return fail(kExitBadInput, "no command (planter-can --help lists them)");
}

// The command on the link, with the whole session logged where --record asks: a log that
// could not be written fails the run (exit 1), whatever the command said.
int run_with_session_log(Cli& o, ToolLink& link, ToolContext& ctx) {
  std::ofstream session_file;
  std::unique_ptr<LogWriter> session_writer;
  if (!o.session_log.empty()) {
    if (const std::string refusal = config::new_log_refusal(o.session_log); !refusal.empty())
      return fail(kExitBadInput, "--record: " + o.session_log + ": " + refusal);
    session_file.open(o.session_log, std::ios::app);  // new: appended, never truncated
    if (!session_file)
      return fail(kExitBadInput, "--record: " + o.session_log + ": cannot be written");
    session_writer = std::make_unique<LogWriter>(session_file, link.name());
    link.set_tap(session_writer.get());
  }
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);
  const int rc = run_command(o, ctx);
  if (session_writer) {
    link.set_tap(nullptr);
    session_file.flush();
    session_file.close();
    if (!session_file)
      return fail(kExitFailed, "--record: " + o.session_log + ": cannot be written (disk full?)");
  }
  return rc;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"planter-can: CAN bus commissioning for the scallion transplanter"};
  app.set_version_flag("--version", std::string("planter-can ") + planter::apps::version());
  app.require_subcommand(1);
  app.fallthrough();  // --json, --board ... may also follow the command
  Cli o;
  add_global_options(app, o);
  add_node_commands(app, o);
  add_traffic_commands(app, o);
  add_commissioning_commands(app, o);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return planter::apps::parse_ended(app, e, "planter-can", argc, argv, kExitBadInput);
  }
  default_sim_board(o);
  config::BoardConfig board;
  const bool have_board = !o.board_path.empty();
  try {
    if (have_board) board = config::load_board(o.board_path);
    for (const auto& w : board.warnings) std::cerr << "planter-can: warning: " << w << "\n";
  } catch (const config::ConfigError& e) {
    return fail(kExitBadInput, e.what());
  }
  const config::BoardConfig* known = have_board ? &board : nullptr;
  if (o.decode->parsed())
    return run_decode(known, o.decode_log, o.decode_out, std::cout, std::cerr);
  if (o.gnss->parsed()) return run_gnss(known, o.gnss_options, std::cout, std::cerr);
  if (o.iface.empty()) return fail(kExitBadInput, "--iface is required (can0, vcan0, ... or sim)");
  std::unique_ptr<ToolLink> link;
  try {
    std::string refusal;
    link = o.iface == "sim" ? open_sim_link(o, board, have_board, refusal)
                            : open_socket_link(o, board, have_board);
    if (!link) return fail(kExitBadInput, refusal);
  } catch (const config::ConfigError& e) {
    return fail(kExitBadInput, e.what());
  } catch (const hal::linux_backend::HalError& e) {
    return fail(kExitBadInput, o.iface + ": " + e.what());
  }
  const bool board_known = have_board || !o.scenario_path.empty();
  ToolContext ctx{*link,     board_known ? &board : nullptr,         o.json,        std::cout,
                  std::cerr, std::int64_t{o.timeout_ms} * 1'000'000, !o.no_progress};
  return run_with_session_log(o, *link, ctx);
}
