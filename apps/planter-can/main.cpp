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

std::atomic<bool> g_stop{false};  // set by SIGINT/SIGTERM: monitor, record, replay end cleanly

void on_signal(int) { g_stop.store(true); }

int fail(int code, const std::string& message) {
  std::cerr << "planter-can: " << message << "\n";
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace planter;
  using namespace planter::cantool;
  CLI::App app{"planter-can: CAN bus commissioning for the scallion transplanter"};
  app.set_version_flag("--version", std::string("planter-can ") + planter::apps::version());
  app.require_subcommand(1);
  app.fallthrough();  // --json, --board ... may also follow the command
  std::string iface, board_path, scenario_path;
  bool json = false, no_progress = false, sim_controller = false, no_sim_controller = false;
  int timeout_ms = 100;
  double push_m = 5.0;
  app.add_option("--iface", iface, "SocketCAN interface (can0, vcan0) or 'sim'");
  app.add_option("--board", board_path, "board file (boards/<board>/board.toml)");
  app.add_flag("--json", json, "machine-readable output");
  app.add_option("--timeout-ms", timeout_ms, "SDO timeout")
      ->check(planter::config::finite_range(1, 60000));
  app.add_flag("--no-progress", no_progress, "no progress line on stderr");
  app.add_option("--sim-scenario", scenario_path, "sim: the machine and field to simulate");
  app.add_flag("--sim-controller", sim_controller,
               "sim: planterd runs on the bus too (SYNC, PDOs, heartbeats); the default but for "
               "configure, calibrate, lss and replay, done with planterd stopped");
  app.add_flag("--no-sim-controller", no_sim_controller,
               "sim: no planterd on the bus (a machine just powered, its nodes pre-operational)");
  std::string session_log;
  app.add_option("--record", session_log,
                 "log the whole session (every frame seen and sent) to this candump -L file");
  app.add_option("--sim-push-m", push_m, "sim: how far the fixture pushes the machine")
      ->check(planter::config::finite_range(0.1, 1000.0));

  ScanOptions scan;
  int listen_ms = 300;
  auto* c_scan = app.add_subcommand("scan", "list the nodes: listen, then probe IDs 1-127");
  c_scan->add_option("--listen-ms", listen_ms, "passive listening first")
      ->check(planter::config::finite_range(0, 60000));
  bool no_probe = false;
  c_scan->add_flag("--passive", no_probe, "listen only, send nothing");

  std::string info_node;
  auto* c_info =
      app.add_subcommand("info", "identity, versions, errors, heartbeat, PDOs of a node");
  c_info->add_option("node", info_node, "node-ID or board role")->required();

  std::vector<std::string> sdo_words;
  std::string sdo_file;
  auto* c_sdo =
      app.add_subcommand("sdo", "CiA 309-3: NODE r IDX SUB [TYPE] | NODE w IDX SUB TYPE VALUE");
  c_sdo->add_option("command", sdo_words, "one command line");
  c_sdo->add_option("-f,--file", sdo_file, "batch file, one command per line");
  c_sdo->allow_extras(false);
  c_sdo->prefix_command();

  std::string nmt_command, nmt_node;
  auto* c_nmt = app.add_subcommand("nmt", "start | stop | preop | reset | reset-comm NODE|all");
  c_nmt->add_option("command", nmt_command)->required();
  c_nmt->add_option("node", nmt_node)->required();

  LssOptions lss;
  std::vector<std::string> lss_identity;
  int lss_timeout_ms = 20;
  auto* c_lss = app.add_subcommand("lss", "fastscan | assign NEW_ID | inquire (CiA 305)");
  c_lss->add_option("action", lss.action)->required();
  c_lss->add_option("new_id", lss.new_id, "assign: the node-ID to give");
  c_lss
      ->add_option("--identity", lss_identity,
                   "VENDOR PRODUCT REVISION SERIAL instead of a fastscan")
      ->expected(4);
  c_lss->add_option("--lss-timeout-ms", lss_timeout_ms, "silence this long means no")
      ->check(planter::config::finite_range(1, 10000));

  ConfigureOptions configure;
  bool no_store = false;
  auto* c_configure =
      app.add_subcommand("configure", "apply the board's node configuration, verify, store");
  c_configure->add_option("--node", configure.node, "only this node (ID or role)");
  c_configure->add_flag("--dry-run", configure.dry_run, "print the SDO writes (CiA 309-3 lines)");
  c_configure->add_flag("--no-store", no_store, "do not store (0x1010) after verifying");

  TrafficOptions traffic;
  traffic.stop = &g_stop;
  auto* c_monitor = app.add_subcommand("monitor", "live decode with names, units and rates");
  c_monitor->add_option("--duration", traffic.duration_s, "seconds (default: until Ctrl-C)")
      ->check(planter::config::finite_range(0.0, 1e7));
  c_monitor->add_flag("--raw", traffic.raw, "raw bytes beside the decode");
  c_monitor->add_flag("--summary-only", traffic.summary_only, "the rate table only");
  c_monitor->add_option("--summary-every", traffic.summary_every_s, "rate table every N seconds")
      ->check(planter::config::finite_range(0.0, 3600.0));

  std::string record_path;
  auto* c_record = app.add_subcommand("record", "candump -L log of the bus, own frames included");
  c_record->add_option("file", record_path)->required();
  c_record->add_option("--duration", traffic.duration_s, "seconds (default: until Ctrl-C)")
      ->check(planter::config::finite_range(0.0, 1e7));

  std::string replay_path;
  auto* c_replay = app.add_subcommand("replay", "send a candump log back onto the bus, timed");
  c_replay->add_option("file", replay_path)->required();
  c_replay
      ->add_option("--max-gap", traffic.max_gap_s, "silences longer than this (s) are shortened")
      ->capture_default_str()
      ->check(planter::config::finite_range(0.001, 3600.0));
  c_replay->add_option("--speed", traffic.speed, "time factor (2 = twice as fast)")
      ->check(planter::config::finite_range(0.001, 1000.0));

  std::string decode_log, decode_out;
  auto* c_decode =
      app.add_subcommand("decode", "candump log -> recording CSV (docs/recording-format.md)");
  c_decode->add_option("log", decode_log)->required();
  c_decode->add_option("-o,--out", decode_out, "CSV file (default: stdout)");

  CalibrateOptions calibrate;
  bool no_write = false;
  auto* c_cal = app.add_subcommand(
      "calibrate", "force | soil-wheel | depth; results into the unit's calibration file");
  c_cal->add_option("what", calibrate.what)->required();
  bool write_sim = false;
  c_cal->add_flag("--write-sim", write_sim,
                  "on --iface sim, write the result into --board's files too (a scratch copy)");
  c_cal->add_option("--known-N", calibrate.known_N, "force: the weight, in newtons")
      ->check(planter::config::finite_range(0.001, 1e5));
  c_cal->add_option("--distance-m", calibrate.distance_m, "soil-wheel: the measured distance")
      ->check(planter::config::finite_range(0.01, 1e4));
  c_cal->add_option("--samples", calibrate.samples, "force: readings per step")
      ->check(planter::config::finite_range(1, 10000));
  c_cal
      ->add_option("--ready-after-s", calibrate.ready_after_s,
                   "scripts: wait this long instead of asking for Enter")
      ->check(planter::config::finite_range(0.0, 3600.0));
  c_cal->add_flag("--no-write", no_write, "show the result, leave the calibration file alone");

  CheckOptions check;
  double check_listen_s = 2.0;
  bool skip_encoder = false;
  GnssOptions gnss;
  gnss.stop = &g_stop;
  auto* c_gnss = app.add_subcommand(
      "gnss", "the GNSS receiver through gpsd: each fix and whether it is used (no bus)");
  c_gnss->add_option("--host", gnss.host, "gpsd's host (default: the board's, else 127.0.0.1)");
  c_gnss->add_option("--port", gnss.port, "gpsd's port (default: the board's, else 2947)")
      ->check(planter::config::finite_range(1, 65535));
  c_gnss->add_option("--duration", gnss.duration_s, "seconds to watch (default 10)")
      ->check(planter::config::finite_range(0.1, 86400.0));
  c_gnss->add_option("--log", gnss.log_path,
                     "check this NMEA log instead (checksums, time, speed)");
  auto* c_check = app.add_subcommand("check", "the commissioning checklist; exit 1 on any fail");
  c_check->add_option("--listen-s", check_listen_s, "how long to watch the bus")
      ->check(planter::config::finite_range(0.1, 600.0));
  c_check->add_option("--max-bus-load", check.max_bus_load_pct, "percent")
      ->check(planter::config::finite_range(1.0, 100.0));
  c_check->add_flag("--skip-encoder", skip_encoder, "do not check the encoder direction");
  c_check->add_option("--mark-commissioned", check.mark_commissioned,
                      "when every item passes, write this stamp (planterd --commissioned-stamp)");
  c_check
      ->add_option("--ready-after-s", check.ready_after_s,
                   "scripts: wait instead of asking for Enter")
      ->check(planter::config::finite_range(0.0, 3600.0));

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return planter::apps::parse_ended(app, e, "planter-can", argc, argv, kExitBadInput);
  }

  // On sim with neither a board nor a scenario: the host-sim board, where the package installs it
  // or in this build's source tree.
  if (iface == "sim" && board_path.empty() && scenario_path.empty()) {
    for (const std::string& candidate :
         {std::string("/etc/planter/boards/host-sim/board.toml"),
          std::string(PLANTER_SOURCE_DIR) + "/boards/host-sim/board.toml"}) {
      std::error_code ec;
      if (std::filesystem::exists(candidate, ec)) {
        board_path = candidate;
        std::cerr << "planter-can: --iface sim with no --board: the host-sim board (" << candidate
                  << ")\n";
        break;
      }
    }
  }
  config::BoardConfig board;
  const bool have_board = !board_path.empty();
  try {
    if (have_board) board = config::load_board(board_path);
    for (const auto& w : board.warnings) std::cerr << "planter-can: warning: " << w << "\n";
  } catch (const config::ConfigError& e) {
    return fail(kExitBadInput, e.what());
  }
  if (c_decode->parsed())
    return run_decode(have_board ? &board : nullptr, decode_log, decode_out, std::cout, std::cerr);

  if (c_gnss->parsed()) return run_gnss(have_board ? &board : nullptr, gnss, std::cout, std::cerr);
  if (iface.empty()) return fail(kExitBadInput, "--iface is required (can0, vcan0, ... or sim)");
  std::unique_ptr<ToolLink> link;
  try {
    if (iface == "sim") {
      sim::Scenario scenario;
      if (!scenario_path.empty()) scenario = sim::load_scenario(scenario_path);
      if (have_board) {
        scenario.board = board;
      } else if (scenario_path.empty()) {
        return fail(
            kExitBadInput,
            "--iface sim needs --board or --sim-scenario (the simulated machine is built from it); "
            "no host-sim board at /etc/planter/boards/host-sim/board.toml or " PLANTER_SOURCE_DIR
            "/boards/host-sim/board.toml");
      } else {
        board = scenario.board;
      }
      SimLinkOptions so;
      // As on the machine: planterd is running, except for what is done with it stopped.
      const bool planterd_stopped =
          c_configure->parsed() || c_cal->parsed() || c_lss->parsed() || c_replay->parsed();
      if (sim_controller && no_sim_controller)
        return fail(kExitBadInput, "--sim-controller and --no-sim-controller: give one");
      so.with_controller = sim_controller || (!no_sim_controller && !planterd_stopped);
      if (c_cal->parsed() && so.with_controller)
        return fail(kExitBadInput,
                    "calibrate needs the machine to itself: planterd must be stopped (leave out "
                    "--sim-controller)");
      so.push_distance_m =
          c_cal->parsed() && calibrate.distance_m > 0 ? calibrate.distance_m : push_m;
      link = std::make_unique<SimLink>(scenario, so);
    } else {
      auto socket = std::make_unique<SocketLink>(iface);
      // The encoder lines are opened only by the commands that need them (planterd may hold them).
      const bool wants_encoder = (c_cal->parsed() && calibrate.what == "soil-wheel") ||
                                 (c_check->parsed() && !skip_encoder);
      if (wants_encoder && have_board && board.gpio.chip != "sim") socket->open_encoder(board);
      link = std::move(socket);
    }
  } catch (const config::ConfigError& e) {
    return fail(kExitBadInput, e.what());
  } catch (const hal::linux_backend::HalError& e) {
    return fail(kExitBadInput, iface + ": " + e.what());
  }
  const bool board_known = have_board || !scenario_path.empty();
  ToolContext ctx{*link,     board_known ? &board : nullptr,       json,        std::cout,
                  std::cerr, std::int64_t{timeout_ms} * 1'000'000, !no_progress};

  std::ofstream session_file;
  std::unique_ptr<LogWriter> session_writer;
  if (!session_log.empty()) {
    if (const std::string refusal = config::new_log_refusal(session_log); !refusal.empty())
      return fail(kExitBadInput, "--record: " + session_log + ": " + refusal);
    session_file.open(session_log, std::ios::app);  // new: appended, never truncated
    if (!session_file)
      return fail(kExitBadInput, "--record: " + session_log + ": cannot be written");
    session_writer = std::make_unique<LogWriter>(session_file, link->name());
    link->set_tap(session_writer.get());
  }
  struct sigaction sa {};
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, nullptr);
  sigaction(SIGTERM, &sa, nullptr);

  // The command, then the session log's own check: a log that could not be written fails
  // the run (exit 1), whatever the command said.
  auto run_command = [&]() -> int {
    if (c_scan->parsed()) {
      scan.listen_ns = std::int64_t{listen_ms} * 1'000'000;
      scan.probe = !no_probe;
      return run_scan(ctx, scan);
    }
    if (c_info->parsed()) return run_info(ctx, info_node);
    if (c_sdo->parsed()) {
      std::vector<SdoLine> lines;
      if (!sdo_file.empty()) {
        std::string error;
        if (!read_batch_file(sdo_file, lines, error)) return fail(kExitBadInput, error);
      }
      if (!sdo_words.empty()) {
        std::string text;
        for (const auto& w : sdo_words) text += (text.empty() ? "" : " ") + w;
        lines.push_back({"command line", text});
      }
      if (lines.empty())
        return fail(kExitBadInput, "sdo: give a command (NODE r IDX SUB [TYPE]) or -f FILE");
      return run_sdo(ctx, lines);
    }
    if (c_nmt->parsed()) return run_nmt(ctx, nmt_command, nmt_node);
    if (c_lss->parsed()) {
      if (!lss_identity.empty()) {
        std::array<std::uint32_t, 4> id{};
        for (std::size_t i = 0; i < 4; ++i) {
          const auto v = parse_integer(lss_identity[i]);
          if (!v || *v < 0 || *v > 0xFFFFFFFF)
            return fail(kExitBadInput,
                        "lss: --identity value '" + lss_identity[i] + "' is not a 32-bit number");
          id[i] = static_cast<std::uint32_t>(*v);
        }
        lss.identity = id;
      }
      lss.timeout_ns = std::int64_t{lss_timeout_ms} * 1'000'000;
      return run_lss(ctx, lss);
    }
    if (c_configure->parsed()) {
      configure.store = !no_store;
      return run_configure(ctx, configure);
    }
    if (c_monitor->parsed()) return run_monitor(ctx, traffic);
    if (c_record->parsed()) return run_record(ctx, record_path, traffic);
    if (c_replay->parsed()) return run_replay(ctx, replay_path, traffic);
    if (c_cal->parsed()) {
      calibrate.write = !no_write;
      // A simulated machine's calibration is no machine's, and the sim's board file is usually
      // the project's own: nothing is written unless asked for (issue 29, the first hour).
      if (iface == "sim" && calibrate.write && !write_sim) {
        calibrate.write = false;
        calibrate.not_written_because = "a simulated machine: --write-sim writes";
        std::cerr << "planter-can: calibrate on --iface sim: the result is shown, not written into "
                  << board_path
                  << " (give --write-sim, with --board a copy of the board, to write it)\n";
      }
      return run_calibrate(ctx, calibrate, std::cin);
    }
    if (c_check->parsed()) {
      check.listen_ns = static_cast<std::int64_t>(check_listen_s * 1e9);
      check.encoder = !skip_encoder;
      return run_check(ctx, check, std::cin);
    }
    return fail(kExitBadInput, "no command (planter-can --help lists them)");
  };
  const int rc = run_command();
  if (session_writer) {
    link->set_tap(nullptr);
    session_file.flush();
    session_file.close();
    if (!session_file) {
      return fail(kExitFailed, "--record: " + session_log + ": cannot be written (disk full?)");
    }
  }
  return rc;
}
