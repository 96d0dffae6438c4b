// Every planter-can command against the simulated nodes on the in-process bus.
#include <fstream>
#include <nlohmann/json.hpp>

#include "apps/planter-can/cmd_calibrate.h"
#include "apps/planter-can/cmd_check.h"
#include "apps/planter-can/cmd_configure.h"
#include "apps/planter-can/cmd_info.h"
#include "apps/planter-can/cmd_lss.h"
#include "apps/planter-can/cmd_scan.h"
#include "apps/planter-can/cmd_sdo.h"
#include "apps/planter-can/cmd_traffic.h"
#include "apps/planter-can/sdo_session.h"
#include "config/commissioning.h"
#include "tests/can/can_tool_fixture.h"

namespace planter::cantool::test {
namespace {

TEST_F(CanToolTest, ScanFindsEveryNodeWithItsIdentityInUnderTwoSeconds) {
  start();
  const ScanResult r = scan_bus(*ctx_, {});
  ASSERT_EQ(r.nodes.size(), 4u);
  EXPECT_EQ(r.probes_sent, 127u);
  EXPECT_LT(r.duration_ns, 2'000'000'000);
  EXPECT_EQ(r.nodes[0].id, 2);
  EXPECT_EQ(r.nodes[0].device_type & 0xFFFF, 402u);
  EXPECT_EQ(r.nodes[0].vendor, 0xABu);
  EXPECT_EQ(r.nodes[0].product, 0x00402001u);
  EXPECT_EQ(r.nodes[0].role, "disc_drive");
  EXPECT_EQ(r.nodes[0].device_name, "sim disc drive");
  EXPECT_EQ(r.nodes[3].device_type & 0xFFFF, 404u);
  EXPECT_EQ(link_->lost_sends(), 0u);
}

TEST_F(CanToolTest, ScanOfASilentBusEndsAtTheTimeout) {
  start({false, false, 5.0});
  for (std::size_t i = 0; i < kNodeCount; ++i)
    link_->rig().endpoint(static_cast<NodeRole>(i)).set_unplugged(true);
  const ScanResult r = scan_bus(*ctx_, {});
  // Their boot-up frames were heard before they went silent; no SDO answer came.
  for (const auto& n : r.nodes) EXPECT_FALSE(n.answered_sdo);
  EXPECT_LT(r.duration_ns, 1'000'000'000);
}

TEST_F(CanToolTest, ScanJsonListsNodes) {
  start();
  ctx_->json = true;
  ASSERT_EQ(run_scan(*ctx_, {}), kExitOk);
  const auto j = nlohmann::json::parse(out());
  EXPECT_EQ(j["nodes"].size(), 4u);
  EXPECT_EQ(j["nodes"][3]["profile"], 404);
}

TEST_F(CanToolTest, ConfigureWritesVerifiesAndStoresWhatTheBoardSays) {
  start();
  ASSERT_EQ(run_configure(*ctx_, {}), kExitOk) << err();
  EXPECT_NE(out().find("disc_drive       node 2"), std::string::npos) << out();
  EXPECT_NE(out().find("stored"), std::string::npos);
  SdoSession sdo(*link_, ctx_->sdo_timeout_ns);
  // The disc drive's TPDO1 carries statusword and velocity actual, valid, every SYNC.
  EXPECT_EQ(sdo.read(2, 0x1A00, 0).value(), 2u);
  EXPECT_EQ(sdo.read(2, 0x1A00, 1).value(), 0x60410010u);
  EXPECT_EQ(sdo.read(2, 0x1A00, 2).value(), 0x606C0020u);
  EXPECT_EQ(sdo.read(2, 0x1800, 1).value(), 0x182u);
  EXPECT_EQ(sdo.read(2, 0x1017, 0).value(), 100u);
  // Stored: a reset node keeps the configuration.
  clear();
  ASSERT_EQ(run_nmt(*ctx_, "reset", "2"), kExitOk);
  EXPECT_EQ(sdo.read(2, 0x1A00, 1).value(), 0x60410010u);
  EXPECT_EQ(sdo.read(2, 0x1017, 0).value(), 100u);
}

TEST_F(CanToolTest, ConfigureWithoutStoreIsLostOnReset) {
  start();
  ConfigureOptions o;
  o.node = "roller_actuator";
  o.store = false;
  ASSERT_EQ(run_configure(*ctx_, o), kExitOk) << err();
  ASSERT_EQ(run_nmt(*ctx_, "reset", "3"), kExitOk);
  SdoSession sdo(*link_, ctx_->sdo_timeout_ns);
  EXPECT_EQ(sdo.read(3, 0x1017, 0).value(), 0u);
}

TEST_F(CanToolTest, ConfigureDryRunPrintsLinesTheSdoCommandAccepts) {
  start();
  ConfigureOptions o;
  o.dry_run = true;
  o.node = "5";
  ASSERT_EQ(run_configure(*ctx_, o), kExitOk);
  const std::string script = out();
  EXPECT_NE(script.find("5 w 0x1A00 1 x32 0x71300110"), std::string::npos) << script;
  // Nothing was written.
  SdoSession sdo(*link_, ctx_->sdo_timeout_ns);
  EXPECT_EQ(sdo.read(5, 0x1017, 0).value(), 0u);
  // Fed back through `sdo`, it configures the node.
  std::vector<SdoLine> lines;
  std::istringstream in(script);
  std::string l;
  while (std::getline(in, l)) {
    if (!l.empty() && l[0] != '#') lines.push_back({"dry-run", l});
  }
  clear();
  ASSERT_EQ(run_sdo(*ctx_, lines), kExitOk) << out() << err();
  EXPECT_EQ(sdo.read(5, 0x1017, 0).value(), 100u);
}

TEST_F(CanToolTest, ConfigureReportsTheStepThatFailed) {
  board_.controller.nodes[0].product_code = 0x12345678;  // not what the drive says
  start();
  ConfigureOptions o;
  o.node = "disc_drive";
  EXPECT_EQ(run_configure(*ctx_, o), kExitFailed);
  EXPECT_NE(out().find("FAILED"), std::string::npos);
  EXPECT_NE(out().find("boot error M"), std::string::npos) << out();
}

TEST_F(CanToolTest, InfoDecodesIdentityHeartbeatAndPdoMaps) {
  start();
  ASSERT_EQ(run_configure(*ctx_, {}), kExitOk);
  link_->rig().drive(NodeRole::kDepthActuator).raise_fault(0x2310);
  clear();
  ASSERT_EQ(run_info(*ctx_, "depth_actuator"), kExitOk) << err();
  const std::string o = out();
  EXPECT_NE(o.find("sim depth actuator"), std::string::npos) << o;
  EXPECT_NE(o.find("CiA 402 drive"), std::string::npos);
  EXPECT_NE(o.find("100 ms"), std::string::npos);
  EXPECT_NE(o.find("0x00002310  current, device output side"), std::string::npos) << o;
  EXPECT_NE(o.find("6077:00/16 torque actual"), std::string::npos) << o;
  EXPECT_EQ(run_info(*ctx_, "plough"), kExitBadInput);
}

TEST_F(CanToolTest, SdoReadsWritesAndExplainsAborts) {
  start();
  std::vector<SdoLine> lines{{"t", "[1] 2 r 0x1018 1"},     {"t", "[2] 2 w 0x1017 0 u16 250"},
                             {"t", "[3] 2 r 0x1017 0"},     {"t", "[4] 2 r 0x1008 0 vs"},
                             {"t", "[5] 2 r 0x2000 0 u32"}, {"t", "[6] 2 w 0x1000 0 u32 1"}};
  EXPECT_EQ(run_sdo(*ctx_, lines), kExitFailed);
  EXPECT_EQ(out(),
            "[1] 0x000000AB\n[2] OK\n[3] 250\n[4] \"sim disc drive\"\n"
            "[5] ERROR: 0x06020000 object does not exist in the object dictionary\n"
            "[6] ERROR: 0x06010002 attempt to write a read-only object\n");
}

TEST_F(CanToolTest, SdoToASilentNodeTimesOutWithAMessage) {
  start();
  EXPECT_EQ(run_sdo(*ctx_, {{"t", "42 r 0x1000 0"}}), kExitFailed);
  EXPECT_EQ(out(), "ERROR: 0x05040000 no answer from node 42 in 100 ms\n");
}

TEST_F(CanToolTest, SdoBatchWithATypoIsNotHalfApplied) {
  std::ofstream(dir_ / "batch.txt") << "# heartbeat\n2 w 0x1017 0 u16 300\n2 w 0x1017 0 u17 300\n";
  std::vector<SdoLine> lines;
  std::string error;
  ASSERT_TRUE(read_batch_file((dir_ / "batch.txt").string(), lines, error));
  start();
  EXPECT_EQ(run_sdo(*ctx_, lines), kExitBadInput);
  EXPECT_NE(err().find("batch.txt:3: token 5 'u17': expected a data type"), std::string::npos)
      << err();
  SdoSession sdo(*link_, ctx_->sdo_timeout_ns);
  EXPECT_EQ(sdo.read(2, 0x1017, 0).value(), 0u);
}

TEST_F(CanToolTest, NmtStartIsConfirmedByTheHeartbeat) {
  start();
  ASSERT_EQ(run_configure(*ctx_, {}), kExitOk);
  clear();
  ASSERT_EQ(run_nmt(*ctx_, "start", "disc_drive"), kExitOk);
  EXPECT_EQ(out(), "start node 2: confirmed, heartbeat says operational\n");
  EXPECT_EQ(link_->rig().drive(NodeRole::kDiscDrive).nmt_state(), canopen::NmtState::kOperational);
  EXPECT_EQ(run_nmt(*ctx_, "begin", "2"), kExitBadInput);
  EXPECT_EQ(run_nmt(*ctx_, "start", "200"), kExitBadInput);
}

TEST_F(CanToolTest, LssFastscanFindsTheUnconfiguredNodeAndAssignGivesItAnId) {
  start();
  LssOptions o;
  o.action = "fastscan";
  ASSERT_EQ(run_lss(*ctx_, o), kExitOk);
  EXPECT_NE(out().find("serial 0x00C0FFEE"), std::string::npos) << out();
  clear();
  o.action = "assign";
  o.new_id = 9;
  ASSERT_EQ(run_lss(*ctx_, o), kExitOk) << out() << err();
  EXPECT_NE(out().find("unconfigured -> 9, stored, boot-up seen"), std::string::npos) << out();
  // It answers SDO as node 9 now, and no unconfigured node is left.
  SdoSession sdo(*link_, ctx_->sdo_timeout_ns);
  EXPECT_EQ(sdo.read(9, 0x1018, 4).value(), 0x00C0FFEEu);
  clear();
  o.action = "fastscan";
  ASSERT_EQ(run_lss(*ctx_, o), kExitOk);
  EXPECT_NE(out().find("no unconfigured node"), std::string::npos);
  // Inquire by identity.
  clear();
  o.action = "inquire";
  o.identity = std::array<std::uint32_t, 4>{0xCD, 0x00404001, 2, 0x00C0FFEE};
  ASSERT_EQ(run_lss(*ctx_, o), kExitOk) << err();
  EXPECT_NE(out().find("node-ID 9"), std::string::npos);
}

TEST_F(CanToolTest, CalibrateForceFindsHiddenOffsetAndSpanAndWritesTheCalibration) {
  scenario_.plant.effects.force_offset_N = 3.0;
  scenario_.plant.effects.force_gain_pct = 8.0;
  start();
  CalibrateOptions o;
  o.what = "force";
  o.known_N = 50.0;
  o.samples = 40;
  std::istringstream in;
  ASSERT_EQ(run_calibrate(*ctx_, o, in), kExitOk) << err();
  const config::BoardConfig after = config::load_board(board_path_);
  const NodeConfig& f = after.controller.node(NodeRole::kForceSensor);
  EXPECT_NEAR(f.zero_counts, 30.0, 3.0);                // 3 N at 10 counts/N
  EXPECT_NEAR(f.counts_per_unit, 10.8, 0.15) << out();  // +8 % span
  // The unit's calibration file took the change; the board (wiring) is as it was.
  const std::string calibration = (dir_ / "calibration.toml").string();
  EXPECT_TRUE(std::filesystem::exists(calibration + ".bak"));
  EXPECT_FALSE(std::filesystem::exists(board_path_ + ".bak"));
  EXPECT_EQ(config::load_board(board_path_, calibration + ".bak")
                .controller.node(NodeRole::kForceSensor)
                .counts_per_unit,
            10.0);
  EXPECT_NE(out().find("nodes.force_sensor.counts_per_unit"), std::string::npos) << out();
  EXPECT_NE(out().find("written to " + calibration), std::string::npos) << out();
}

TEST_F(CanToolTest, CalibrateSoilWheelMeasuresTheEffectiveRadius) {
  scenario_.plant.soil.slip_mean_pct = 3.0;
  scenario_.plant.route.speed_mps = 0.5;
  scenario_.plant.route.accel_mps2 = 0.5;
  start({false, true, 4.0});
  CalibrateOptions o;
  o.what = "soil-wheel";
  o.distance_m = 4.0;
  std::istringstream in;
  ASSERT_EQ(run_calibrate(*ctx_, o, in), kExitOk) << err();
  const double r = config::load_board(board_path_).controller.encoder.wheel_radius_m;
  EXPECT_NEAR(r, 0.150 / 0.97, 0.002);
}

TEST_F(CanToolTest, CalibrateDepthHomesAndFindsTheEndStop) {
  start();
  ASSERT_EQ(run_configure(*ctx_, {}), kExitOk);
  CalibrateOptions o;
  o.what = "depth";
  std::istringstream in;
  ASSERT_EQ(run_calibrate(*ctx_, o, in), kExitOk) << err();
  const config::BoardConfig after = config::load_board(board_path_);
  EXPECT_NEAR(after.controller.depth.max_mm, 165.0, 0.5);  // the sim's end stop
  EXPECT_NEAR(after.controller.depth.min_mm, 0.0, 0.1);
}

TEST_F(CanToolTest, CalibrateWithoutAPersonOrFixtureRefuses) {
  start();
  CalibrateOptions o;
  o.what = "force";
  std::istringstream in;
  EXPECT_EQ(run_calibrate(*ctx_, o, in), kExitBadInput);  // no --known-N
  o.what = "weight";
  EXPECT_EQ(run_calibrate(*ctx_, o, in), kExitBadInput);
}

TEST_F(CanToolTest, CheckPassesOnAHealthyRunningMachine) {
  start({true, false, 1.0});
  // planterd boots the nodes and starts them; give it a moment.
  hal::CanFrame f;
  while (link_->receive_until(f, 2'000'000'000)) {
  }
  ASSERT_EQ(link_->controller()->state(), SupervisorState::kReady);
  CheckOptions o;
  ctx_->json = true;
  ASSERT_EQ(run_check(*ctx_, o, std::cin), kExitOk) << out();
  const auto j = nlohmann::json::parse(out());
  EXPECT_TRUE(j["passed"].get<bool>());
  EXPECT_GE(j["items"].size(), 20u);
}

TEST_F(CanToolTest, OnlyAPassingCheckMarksTheBoardCommissioned) {
  const std::string stamp = (dir_ / "commissioned").string();
  std::string why;
  EXPECT_FALSE(config::commissioned(stamp, board_path_, why));
  EXPECT_NE(why.find("no commissioning stamp"), std::string::npos);
  start({false, false, 1.0});  // no planterd: the check fails, no stamp
  CheckOptions o;
  o.mark_commissioned = stamp;
  EXPECT_EQ(run_check(*ctx_, o, std::cin), kExitFailed);
  EXPECT_FALSE(std::filesystem::exists(stamp));
  start({true, false, 1.0});
  link_->idle_until(2'000'000'000);
  clear();
  ASSERT_EQ(run_check(*ctx_, o, std::cin), kExitOk) << out();
  EXPECT_NE(out().find("commissioned: "), std::string::npos);
  EXPECT_TRUE(config::commissioned(stamp, board_path_, why)) << why;
  // Editing the board afterwards asks for a new check.
  std::ofstream(board_path_, std::ios::app) << "# edited\n";
  EXPECT_FALSE(config::commissioned(stamp, board_path_, why));
  EXPECT_NE(why.find("changed since it was commissioned"), std::string::npos);
  // So does a new calibration: the stamp covers the unit's calibration file too.
  std::string error;
  ASSERT_TRUE(config::write_commissioning_stamp(stamp, board_path_, "host-sim", 0, error)) << error;
  EXPECT_TRUE(config::commissioned(stamp, board_path_, why)) << why;
  std::ofstream(dir_ / "calibration.toml", std::ios::app) << "# re-measured\n";
  EXPECT_FALSE(config::commissioned(stamp, board_path_, why));
}

TEST_F(CanToolTest, CheckFailsWithoutTrafficAndOnSwappedEncoderLines) {
  start({false, false, 1.0});
  CheckOptions o;
  EXPECT_EQ(run_check(*ctx_, o, std::cin), kExitFailed);
  EXPECT_NE(out().find("FAIL  SYNC rate"), std::string::npos) << out();
  EXPECT_NE(out().find("none in 2.0 s"), std::string::npos);
  EXPECT_NE(out().find("pass  encoder direction"), std::string::npos);
}

TEST_F(CanToolTest, CheckFindsSwappedEncoderWires) {
  SimLinkOptions o{false, false, 1.0};
  o.encoder_wires_swapped = true;
  start(o);
  EXPECT_EQ(run_check(*ctx_, {}, std::cin), kExitFailed);
  EXPECT_NE(out().find("FAIL  encoder direction"), std::string::npos) << out();
  EXPECT_NE(out().find("A and B are swapped"), std::string::npos);
}

TEST_F(CanToolTest, MonitorDecodesPdosWithNamesAndUnits) {
  start({true, false, 1.0});
  TrafficOptions o;
  o.duration_s = 1.5;
  ASSERT_EQ(run_monitor(*ctx_, o), kExitOk);
  const std::string m = out();
  EXPECT_NE(m.find("disc_drive(2)"), std::string::npos) << m.substr(0, 2000);
  EXPECT_NE(m.find("clamp_force"), std::string::npos);  // the signal table's name
  EXPECT_NE(m.find(" N"), std::string::npos);
  EXPECT_NE(m.find("SYNC"), std::string::npos);
  // The rate table: SYNC at 100 Hz.
  EXPECT_NE(m.find("0x080 SYNC"), std::string::npos);
  EXPECT_NE(m.find("100.0"), std::string::npos);
}

TEST_F(CanToolTest, ReplaySendsTheLogInOrderAndOnTime) {
  const std::string log = (dir_ / "nmt.log").string();
  std::ofstream(log) << "(1000.000000) can0 000#0102\n(1000.000000) can0 000#0103\n"
                        "(1000.500000) can0 000#0104\n(1000.499000) can0 000#0105\n";
  start();
  // Watch the bus from a second endpoint.
  auto& watcher = link_->bus().add_endpoint(64);
  TrafficOptions o;
  const std::int64_t t0 = link_->now_ns();
  ASSERT_EQ(run_replay(*ctx_, log, o), kExitOk) << err();
  EXPECT_NE(out().find("4 of 4 frames replayed"), std::string::npos);
  EXPECT_GE(link_->now_ns() - t0, 500'000'000);  // the log's half second, not faster
  hal::CanFrame f;
  std::vector<int> nodes;
  while (watcher.receive(f)) {
    if (f.cob_id() == 0) nodes.push_back(f.data[1]);
  }
  EXPECT_EQ(nodes, (std::vector<int>{2, 3, 4, 5}));  // file order, the early stamp too
}

TEST_F(CanToolTest, RecordKeepsTheToolsOwnFramesAndDecodeMakesTheRecordingCsv) {
  start({true, false, 1.0});
  const std::string log = (dir_ / "bus.log").string();
  TrafficOptions o;
  o.duration_s = 3.0;
  ASSERT_EQ(run_record(*ctx_, log, o), kExitOk);
  std::ifstream in(log);
  std::string line;
  int lines = 0, rpdos = 0;
  while (std::getline(in, line)) {
    ++lines;
    ASSERT_EQ(line[0], '(');
    if (line.find(" sim 202#") != std::string::npos) ++rpdos;
  }
  EXPECT_GT(lines, 500);
  // The controller booted the nodes before the tool was connected: its commands to the disc
  // drive are on the bus every cycle.
  EXPECT_GT(rpdos, 250);
  const std::string csv = (dir_ / "bus.csv").string();
  std::ostringstream out, err;
  ASSERT_EQ(run_decode(&board_, log, csv, out, err), kExitOk) << err.str();
  std::ifstream c(csv);
  std::string header;
  while (std::getline(c, header) && header[0] == '#') {
  }
  EXPECT_EQ(header,
            "t,omega_cmd,omega,disc_angle,disc_torque,clamp_pos_mm,clamp_force,depth_cmd_mm,depth_"
            "mm,depth_force");
  int rows = 0;
  while (std::getline(c, line)) ++rows;
  EXPECT_GT(rows, 50);

  // Issue 53, item 6: the same log with every TPDO a byte short, and with every time the same,
  // is refused (exit 1, said), not written as a recording of fewer columns or of one row.
  const auto rewrite = [&](const std::string& name, auto&& edit) {
    std::ifstream src(log);
    std::ofstream dst((dir_ / name).string());
    for (std::string l; std::getline(src, l);) dst << edit(l) << "\n";
    return (dir_ / name).string();
  };
  const std::string short_log = rewrite("short.log", [](std::string l) {
    const auto hash = l.find('#');
    const int id =
        std::stoi(l.substr(l.rfind(' ', hash) + 1, hash - l.rfind(' ', hash) - 1), nullptr, 16);
    const int fn = id & 0x780;
    const bool tpdo = fn == 0x180 || fn == 0x280 || fn == 0x380 || fn == 0x480;
    if (tpdo && l.size() >= hash + 3) l.resize(l.size() - 2);
    return l;
  });
  std::ostringstream out2, err2;
  EXPECT_EQ(run_decode(&board_, short_log, (dir_ / "short.csv").string(), out2, err2), kExitFailed);
  EXPECT_NE(err2.str().find("PDOs do not match the board's maps"), std::string::npos) << err2.str();
  EXPECT_FALSE(std::filesystem::exists(dir_ / "short.csv"));
  const std::string same_log = rewrite(
      "same.log", [](std::string l) { return "(1700000000.000000)" + l.substr(l.find(')') + 1); });
  std::ostringstream out3, err3;
  EXPECT_EQ(run_decode(&board_, same_log, (dir_ / "same.csv").string(), out3, err3), kExitFailed);
  EXPECT_NE(err3.str().find("timestamps do not advance"), std::string::npos) << err3.str();
  EXPECT_FALSE(std::filesystem::exists(dir_ / "same.csv"));
}

}  // namespace
}  // namespace planter::cantool::test
