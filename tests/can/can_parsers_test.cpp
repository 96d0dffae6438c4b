// The tool's parsers and decoders, and SDO transfers against a server that misbehaves.
#include <gtest/gtest.h>
#include <unistd.h>

#include <deque>
#include <filesystem>
#include <functional>

#include "apps/planter-can/board_file_edit.h"
#include "apps/planter-can/candump_log.h"
#include "apps/planter-can/cia309_command.h"
#include "apps/planter-can/frame_decoder.h"
#include "apps/planter-can/sdo_session.h"
#include "apps/planter-can/value_codec.h"
#include "config/board_config.h"
#include "tests/board_copy.h"

namespace planter::cantool::test {
namespace {

hal::CanFrame make(std::uint32_t id, std::vector<std::uint8_t> bytes) {
  hal::CanFrame f{};
  f.id = id;
  f.dlc = static_cast<std::uint8_t>(bytes.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) f.data[i] = bytes[i];
  return f;
}

// A bus where the test plays the node: `reply` sees every frame the tool sends and returns
// what the node answers (1 ms later).
class ScriptedLink final : public ToolLink {
 public:
  std::function<std::vector<hal::CanFrame>(const hal::CanFrame&)> reply;
  std::vector<hal::CanFrame> sent;

  bool wait(std::int64_t deadline_ns) override {
    if (!rx_.empty()) return true;
    if (now_ >= deadline_ns) return false;
    now_ = deadline_ns;
    return false;
  }
  std::int64_t now_ns() override { return now_; }
  std::int64_t wall_time_ns() override { return now_; }
  [[nodiscard]] std::string name() const override { return "script"; }
  [[nodiscard]] hal::CanBusCounters counters() const override { return {}; }

 protected:
  bool try_send(const hal::CanFrame& f) override {
    sent.push_back(f);
    if (reply) {
      for (const auto& r : reply(f)) rx_.push_back(r);
    }
    now_ += 1'000'000;
    return true;
  }
  bool try_receive(hal::CanFrame& f) override {
    if (rx_.empty()) return false;
    f = rx_.front();
    rx_.pop_front();
    return true;
  }
  void back_off() override { now_ += 1'000'000; }

 private:
  std::int64_t now_ = 0;
  std::deque<hal::CanFrame> rx_;
};

TEST(Cia309, ParsesReadsWritesAndNmt) {
  auto p = parse_cia309("[7] 1 5 r 0x1018 2 x32");
  ASSERT_TRUE(std::holds_alternative<Cia309Command>(p));
  auto c = std::get<Cia309Command>(p);
  EXPECT_EQ(c.sequence, 7u);
  EXPECT_EQ(c.net, 1);
  EXPECT_EQ(c.node, 5);
  EXPECT_EQ(c.index, 0x1018);
  EXPECT_EQ(c.sub, 2);
  EXPECT_EQ(c.type->name, "x32");
  c = std::get<Cia309Command>(parse_cia309("4 w 0x1017 0 u16 250"));
  EXPECT_EQ(c.kind, Cia309Command::Kind::kWrite);
  EXPECT_EQ(c.value, (std::vector<std::uint8_t>{250, 0}));
  c = std::get<Cia309Command>(parse_cia309("4 write 0x1008 0 vs \"disc drive 2\""));
  EXPECT_EQ(std::string(c.value.begin(), c.value.end()), "disc drive 2");
  c = std::get<Cia309Command>(parse_cia309("0 reset comm"));
  EXPECT_EQ(c.kind, Cia309Command::Kind::kNmt);
  EXPECT_EQ(c.nmt, canopen::NmtCommand::kResetCommunication);
  c = std::get<Cia309Command>(parse_cia309("3 w 0x60FF 0 i32 -1500"));
  EXPECT_EQ(c.value, (std::vector<std::uint8_t>{0x24, 0xFA, 0xFF, 0xFF}));
  c = std::get<Cia309Command>(parse_cia309("3 w 0x6126 1 r32 1.5"));
  EXPECT_EQ(c.value, (std::vector<std::uint8_t>{0x00, 0x00, 0xC0, 0x3F}));
}

TEST(Cia309, ErrorsNameTheBadToken) {
  auto error = [](const char* line) {
    auto p = parse_cia309(line);
    EXPECT_TRUE(std::holds_alternative<Cia309Error>(p)) << line;
    return std::holds_alternative<Cia309Error>(p) ? std::get<Cia309Error>(p).text() : "";
  };
  EXPECT_EQ(error("5 r 0x10000 0"),
            "token 3 '0x10000': expected an object index from 0x0000 to 0xFFFF");
  EXPECT_EQ(error("5 w 0x1017 0 u16 70000"),
            "token 6 '70000': expected an unsigned integer from 0 to 65535");
  EXPECT_EQ(error("5 w 0x1017 0 u16"), "token 6 '<end of line>': expected a value of type u16");
  // Reals a device would take as +inf or NaN are refused, not encoded.
  EXPECT_EQ(error("3 w 0x6126 1 r32 1e39"),
            "token 6 '1e39': expected a finite real number within +-3.4e38 (r32)");
  EXPECT_EQ(error("3 w 0x6126 1 r32 nan"),
            "token 6 'nan': expected a finite real number within +-3.4e38 (r32)");
  EXPECT_EQ(error("3 w 0x6126 1 r64 -inf"), "token 6 '-inf': expected a finite real number (r64)");
  EXPECT_EQ(error("5 w 0x1017 0 i8 -129"), "token 6 '-129': expected an integer from -128 to 127");
  EXPECT_EQ(error("128 r 0x1000 0"),
            "token 1 '128': expected a node-ID from 1 to 127 (0 = all, NMT only)");
  EXPECT_EQ(error("0 r 0x1000 0"),
            "token 1 '0': expected a node-ID from 1 to 127 (SDO needs one node)");
  EXPECT_EQ(error("5 reset all"), "token 3 'all': expected 'node' or 'comm' after reset");
  EXPECT_EQ(error("5 start now"), "token 3 'now': expected the end of the line");
  EXPECT_EQ(error("[x] 5 start"), "token 1 '[x]': expected a sequence number [0-4294967295]");
  EXPECT_EQ(error("5 w 0x1008 0 os 0G"), "token 6 '0G': expected hex bytes, found '0G'");
  EXPECT_EQ(error("5 r 0x1000 0 f32"),
            std::string("token 5 'f32': expected a data type: ") + value_type_names());
  EXPECT_NE(error("").find("empty command"), std::string::npos);
}

TEST(ValueCodec, FormatsWhatItEncodes) {
  for (const char* t : {"i8", "i16", "i32", "i64"}) {
    const auto type = *parse_value_type(t);
    std::string why;
    EXPECT_EQ(format_value(type, *encode_value(type, "-5", why)), "-5") << t;
  }
  const auto u64 = *parse_value_type("u64");
  std::string why;
  EXPECT_EQ(format_value(u64, *encode_value(u64, "18446744073709551615", why)),
            "18446744073709551615");
  EXPECT_FALSE(encode_value(u64, "-1", why).has_value());
  EXPECT_EQ(format_value(*parse_value_type("x16"), {0x34, 0x12}), "0x1234");
  EXPECT_EQ(format_value(*parse_value_type("os"), {0xDE, 0xAD}), "DE AD");
  EXPECT_EQ(format_value(*parse_value_type("vs"), {'a', 0x01, 'b'}), "\"a?b\"");
}

TEST(CandumpLog, RoundTripsEveryKindOfFrame) {
  const std::vector<hal::CanFrame> frames{
      make(0x080, {}), make(0x602, {0x40, 0x00, 0x10, 0x00, 0, 0, 0, 0}),
      make(0x123 | hal::CanFrame::kRemoteFlag, {}),
      make(0x18FF0001u | hal::CanFrame::kExtendedFlag, {1, 2, 3}),
      make(0x00000004u | hal::CanFrame::kErrorFlag, {0, 0, 0, 0, 0, 0, 0, 0})};
  for (const auto& f : frames) {
    const std::string line = format_log_line(1'700'000'000'123'456'000, "can0", f);
    const LogParse p = parse_log_line(line);
    ASSERT_EQ(p.kind, LogLineKind::kFrame) << line << ": " << p.error;
    EXPECT_EQ(p.record.frame.id, f.id) << line;
    EXPECT_EQ(p.record.frame.dlc, (f.id & hal::CanFrame::kRemoteFlag) ? 0 : f.dlc) << line;
    EXPECT_EQ(p.record.time_ns, 1'700'000'000'123'456'000) << line;
    EXPECT_EQ(p.record.interface, "can0");
  }
  EXPECT_EQ(format_log_line(1'000'000, "vcan0", make(0x702, {0x05})),
            "(0000000000.001000) vcan0 702#05");
}

TEST(CandumpLog, RejectsMalformedLinesWithAReason) {
  EXPECT_EQ(parse_log_line("# a comment").kind, LogLineKind::kSkip);
  EXPECT_EQ(parse_log_line("").kind, LogLineKind::kSkip);
  for (const char* bad :
       {"(12.5 can0 123#00", "(1.000001) can0", "(1.000001) can0 123", "(1.000001) can0 1234#00",
        "(1.000001) can0 123#0", "(1.000001) can0 123#001122334455667788",
        "(1.000001) can0 123##100", "(x.1) can0 123#00", "(1.000001) can0 80000123#00"}) {
    const LogParse p = parse_log_line(bad);
    EXPECT_EQ(p.kind, LogLineKind::kError) << bad;
    EXPECT_FALSE(p.error.empty()) << bad;
  }
}

TEST(FrameDecoder, NamesEveryServiceAndFlagsShortFrames) {
  const config::BoardConfig board =
      config::load_board(std::string(PLANTER_SOURCE_DIR) + "/boards/host-sim/board.toml");
  const FrameDecoder d(&board.controller);
  EXPECT_EQ(d.decode(make(0x000, {0x01, 0x02})).text, "start node 2");
  EXPECT_EQ(d.decode(make(0x702, {0x05})).text, "operational");
  EXPECT_EQ(d.decode(make(0x702, {0x05})).node_name, "disc_drive");
  EXPECT_EQ(d.decode(make(0x082, {0x10, 0x23, 0x01, 0, 0, 0, 0, 0})).text,
            "EMCY 0x2310 current, device output side (overcurrent), error register 0x01");
  EXPECT_EQ(d.decode(make(0x582, {0x80, 0x00, 0x20, 0x00, 0x00, 0x00, 0x02, 0x06})).text,
            "abort 2000:00 ?: 0x06020000 object does not exist in the object dictionary");
  EXPECT_EQ(d.decode(make(0x602, {0x40, 0x18, 0x10, 0x01, 0, 0, 0, 0})).text,
            "read 1018:01 vendor-ID");
  // The force sensor's TPDO1: 7130:01 in 0.1 N -> newtons.
  const DecodedFrame f = d.decode(make(0x185, {0x84, 0x03}));
  ASSERT_EQ(f.values.size(), 1u);
  EXPECT_DOUBLE_EQ(f.values[0].value, 90.0);
  EXPECT_EQ(f.values[0].unit, "N");
  // The disc drive's TPDO1: statusword and velocity (counts/s -> rad/s).
  const DecodedFrame v = d.decode(make(0x182, {0x37, 0x02, 0x53, 0x7F, 0x00, 0x00}));
  ASSERT_EQ(v.values.size(), 2u);
  EXPECT_NEAR(v.values[1].value, 32595.0 / 32595.0, 1e-9);
  EXPECT_EQ(v.values[1].unit, "rad/s");
  EXPECT_NE(v.text.find("operation enabled"), std::string::npos) << v.text;
  // Short frames are flagged, never read past their length.
  EXPECT_TRUE(d.decode(make(0x182, {0x37})).malformed);
  EXPECT_TRUE(d.decode(make(0x000, {0x01})).malformed);
  EXPECT_TRUE(d.decode(make(0x082, {0x10})).malformed);
  EXPECT_TRUE(d.decode(make(0x702, {})).malformed);
  EXPECT_EQ(d.decode(make(0x7E5, {0x51})).service, Service::kLssMaster);
  EXPECT_EQ(d.decode(make(0x123 | hal::CanFrame::kErrorFlag, {})).service, Service::kErrorFrame);
}

// SDO responses that are garbage, truncated, reordered or missing end in a clean error.
TEST(SdoSession, GarbageTruncatedReorderedAndMissingResponsesFailCleanly) {
  ScriptedLink link;
  SdoSession sdo(link, 100'000'000);
  // Garbage command byte (answered only to the request, not to the abort that follows).
  link.reply = [](const hal::CanFrame& f) -> std::vector<hal::CanFrame> {
    if (f.cob_id() != 0x605 || f.data[0] != 0x40) return {};
    return {make(0x585, {0xE7, 1, 2, 3, 4, 5, 6, 7})};
  };
  SdoResult r = sdo.read(5, 0x1000, 0);
  EXPECT_EQ(r.status, SdoResult::Status::kAborted);
  EXPECT_EQ(r.abort_code, canopen::abort_code::kBadCommand);
  // Truncated: an expedited answer with only 5 bytes takes just the byte that came.
  link.reply = [](const hal::CanFrame& f) -> std::vector<hal::CanFrame> {
    if (f.cob_id() != 0x605 || f.data[0] != 0x40) return {};
    return {make(0x585, {0x43, 0x00, 0x10, 0x00, 0x92})};
  };
  r = sdo.read(5, 0x1000, 0);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r.data.size(), 1u);
  // Reordered: the answer names another object (a late reply to an earlier request).
  link.reply = [](const hal::CanFrame& f) -> std::vector<hal::CanFrame> {
    if (f.cob_id() != 0x605 || f.data[0] != 0x40) return {};
    return {make(0x585, {0x43, 0x18, 0x10, 0x01, 0xAB, 0, 0, 0})};
  };
  r = sdo.read(5, 0x1000, 0);
  EXPECT_EQ(r.status, SdoResult::Status::kAborted);
  EXPECT_EQ(link.sent.back().data[0], 0x80);  // the tool aborted the transfer on the bus
  // Segments with the toggle bit wrong.
  link.reply = [](const hal::CanFrame& f) -> std::vector<hal::CanFrame> {
    if (f.cob_id() != 0x605) return {};
    if (f.data[0] == 0x40) return {make(0x585, {0x41, 0x08, 0x10, 0x00, 20, 0, 0, 0})};
    return {make(0x585, {0x10, 'a', 'b', 'c', 'd', 'e', 'f', 'g'})};  // toggle 1 first: wrong
  };
  r = sdo.read(5, 0x1008, 0);
  EXPECT_EQ(r.abort_code, canopen::abort_code::kToggleBit);
  // Silence: a timeout after 100 ms, and an abort sent.
  link.reply = nullptr;
  const std::int64_t t0 = link.now_ns();
  r = sdo.read(5, 0x1000, 0);
  EXPECT_EQ(r.status, SdoResult::Status::kTimedOut);
  EXPECT_LE(link.now_ns() - t0, 110'000'000);
  EXPECT_EQ(r.error_text(5, 100'000'000), "timeout: no answer from node 5 in 100 ms");
}

TEST(BoardFileEdit, ChangesOnlyTheKeysAndKeepsComments) {
  std::string text =
      "[encoder]\ncounts_per_rev = 4096   # x4\nwheel_radius_m = 0.15  # calibrated\n\n"
      "[nodes.force_sensor]\nid = 5\n";
  edit_board_text(
      text, {{"encoder", "wheel_radius_m", "0.1546"}, {"nodes.force_sensor", "zero_counts", "31"}});
  EXPECT_EQ(text,
            "[encoder]\ncounts_per_rev = 4096   # x4\nwheel_radius_m = 0.1546  # calibrated\n\n"
            "[nodes.force_sensor]\nid = 5\nzero_counts = 31\n");
  // A table the file lacks is added at its end (a calibration starts with few tables).
  edit_board_text(text, {{"control", "depth_max_mm", "165"}});
  EXPECT_NE(text.find("zero_counts = 31\n\n[control]\ndepth_max_mm = 165\n"), std::string::npos)
      << text;
}

// A calibration reached through a symlink (as a unit's may be) stays a link, and a second
// calibration keeps the first one's backup.
TEST(BoardFileEdit, FollowsSymlinksAndNeverOverwritesABackup) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / ("planter-edit-" + std::to_string(::getpid()));
  fs::remove_all(dir);
  const std::string board = planter::test::copy_board("host-sim", dir).string();
  fs::rename(dir / "calibration.toml", dir / "unit-0042.toml");
  fs::create_symlink(dir / "unit-0042.toml", dir / "calibration.toml");
  const double original = config::load_board(board).controller.encoder.wheel_radius_m;
  std::string error, backup, written;
  ASSERT_TRUE(
      write_board_edits(board, {{"encoder", "wheel_radius_m", "0.1546"}}, error, &backup, &written))
      << error;
  EXPECT_EQ(written, (dir / "unit-0042.toml").string());
  EXPECT_TRUE(fs::is_symlink(dir / "calibration.toml"));
  EXPECT_EQ(backup, (dir / "unit-0042.toml.bak").string());
  ASSERT_TRUE(write_board_edits(board, {{"encoder", "wheel_radius_m", "0.1551"}}, error, &backup))
      << error;
  EXPECT_EQ(backup, (dir / "unit-0042.toml.bak.2").string());
  EXPECT_TRUE(fs::is_symlink(dir / "calibration.toml"));
  auto radius_with = [&](const fs::path& calibration) {
    return config::load_board(board, calibration.string()).controller.encoder.wheel_radius_m;
  };
  EXPECT_DOUBLE_EQ(radius_with(dir / "unit-0042.toml.bak"), original);
  EXPECT_DOUBLE_EQ(radius_with(dir / "unit-0042.toml.bak.2"), 0.1546);
  EXPECT_DOUBLE_EQ(config::load_board(board).controller.encoder.wheel_radius_m, 0.1551);
  // An edit the board would not load with is refused and leaves the file as it was.
  EXPECT_FALSE(write_board_edits(board, {{"encoder", "wheel_radius_m", "7"}}, error));
  EXPECT_NE(error.find("would not load"), std::string::npos) << error;
  EXPECT_DOUBLE_EQ(config::load_board(board).controller.encoder.wheel_radius_m, 0.1551);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace planter::cantool::test
