// The signal table (firmware/io/signal_table.h) is the one declaration of every recording
// column: the recording format's columns (docs/recording-format.md) match it name for name and unit
// for unit, the recording header comes from it, and what planter-can decodes from the bus (decode
// and monitor share FrameDecoder) is what the controller's telemetry holds, on a live lockstep run.
#include "firmware/io/signal_table.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "apps/planter-can/frame_decoder.h"
#include "config/recording_format.h"
#include "sim/runner/lockstep_runner.h"

using namespace planter;

namespace {

// The first `| name | unit | meaning |` table under a heading of a markdown file: name -> unit.
std::map<std::string, std::string> columns_table(const std::string& file,
                                                 const std::string& heading) {
  std::ifstream in(file);
  std::map<std::string, std::string> cols;
  std::string line;
  bool under_heading = false, in_table = false;
  while (std::getline(in, line)) {
    if (line == heading) under_heading = true;
    if (under_heading && line.rfind("| name | unit | meaning |", 0) == 0) {
      in_table = true;
      continue;
    }
    if (!in_table) continue;
    if (line.empty() || line[0] != '|') break;
    if (line.rfind("|---", 0) == 0) continue;
    std::stringstream ss(line.substr(1));
    std::string name, unit;
    std::getline(ss, name, '|');
    std::getline(ss, unit, '|');
    auto trim = [](std::string s) {
      s.erase(0, s.find_first_not_of(' '));
      s.erase(s.find_last_not_of(' ') + 1);
      return s;
    };
    cols[trim(name)] = trim(unit);
  }
  return cols;
}
// The recording format's columns of the controller, as the brief gave them
// (docs/recording-format.md, the project's own copy of the format).
const std::string kFormat = std::string(PLANTER_SOURCE_DIR) + "/docs/recording-format.md";
std::map<std::string, std::string> product_columns() {
  return columns_table(kFormat, "## The controller's columns");
}
// The planting monitor's columns, which the project adds after the controller's.
std::map<std::string, std::string> readme_monitor_columns() {
  return columns_table(kFormat, "## Columns this project adds");
}

}  // namespace

TEST(SignalTable, EveryColumnIsDeclaredOnceWithProductsUnit) {
  const auto product = product_columns();
  ASSERT_GE(product.size(), 15u)
      << "docs/recording-format.md's table of the controller's columns was not found";
  std::multiset<std::string_view> declared;
  for (const SignalDecl& s : kSignals) declared.insert(s.column);
  const auto monitor = readme_monitor_columns();
  ASSERT_GE(monitor.size(), 10u) << "docs/recording-format.md's table of our columns was not found";
  for (const SignalDecl& s : kSignals) {
    EXPECT_EQ(declared.count(s.column), 1u) << s.column;
    if (!s.recorded) continue;
    // The planting monitor's columns and the operator's depth target are this project's,
    // documented among the columns this project adds; the rest are the brief's.
    const bool ours =
        s.source == SignalSource::kMonitor || s.source == SignalSource::kWarnings ||
        (monitor.count(std::string(s.column)) && !product.count(std::string(s.column)));
    const auto& table = ours ? monitor : product;
    const auto it = table.find(std::string(s.column));
    ASSERT_NE(it, table.end()) << s.column << " is recorded but not in "
                               << (ours ? "the format's table of our columns"
                                        : "the format's controller columns");
    EXPECT_EQ(it->second, s.unit) << s.column;
    EXPECT_FALSE(ours && product.count(std::string(s.column)))
        << s.column << " is one of the controller's columns";
  }
  for (const auto& [name, unit] : monitor) EXPECT_NE(find_signal(name), nullptr) << name;
  // Every controller column of the format is declared, except v_ground: an independent speed sensor
  // the controller does not have (the simulator writes its truth under that name).
  for (const auto& [name, unit] : product) {
    if (name == "v_ground") continue;
    const SignalDecl* s = find_signal(name);
    ASSERT_NE(s, nullptr) << name << " is in the recording format but not declared";
    EXPECT_TRUE(s->recorded) << name;
  }
}

TEST(SignalTable, RecordingHeaderAndRowComeFromTheTable) {
  std::string expected;
  std::size_t recorded = 0;
  for (const SignalDecl& s : kSignals) {
    if (!s.recorded) continue;
    if (!expected.empty()) expected += ',';
    expected += s.column;
    ++recorded;
  }
  EXPECT_EQ(config::controller_columns(), expected);
  Telemetry t;
  t.clamp_force_N = 91.25;
  t.depth_cmd_mm = 102.0;
  char row[512];
  const int n = config::format_controller_columns(row, sizeof row, 1.5, t);
  ASSERT_GT(n, 0);
  const std::string r(row, static_cast<std::size_t>(n));
  EXPECT_EQ(static_cast<std::size_t>(std::count(r.begin(), r.end(), ',')), recorded - 1) << r;
  EXPECT_NE(r.find(",91.25,"), std::string::npos) << r;
  EXPECT_NE(r.find(",102.000,"), std::string::npos) << r;
  // A buffer too small is reported, never overrun.
  char tiny[8];
  EXPECT_GE(config::format_controller_columns(tiny, sizeof tiny, 1.5, t), 8);
}

// The recording's numbers are written without printf (issue 30) and must stay "%.*f" byte
// for byte: ties (0.125 at two decimals), signed zeros, tiny negatives, large and non-finite
// values, and a million random values across the recording's magnitudes and decimals.
TEST(SignalTable, RowNumbersAreWhatPrintfWrites) {
  const auto printf_of = [](double v, int decimals) {
    char buf[400];
    const int n = std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return std::string(buf, static_cast<std::size_t>(n));
  };
  const auto ours = [](double v, int decimals) {
    char buf[400];
    config::RowText row(buf, sizeof buf);
    row.fixed(v, decimals);
    return std::string(buf, row.length());
  };
  std::vector<std::pair<double, int>> cases = {
      {0.125, 2},   {0.375, 2}, {2.5, 0},    {3.5, 0},      {-0.0, 3},     {0.0, 5},
      {-0.0001, 3}, {1e-7, 5},  {-1e-7, 4},  {0.5, 0},      {1.0005, 3},   {-2.675, 2},
      {1e300, 2},   {-1e20, 1}, {4.5e15, 3}, {9.999995, 5}, {123456.5, 0}, {0.05, 1}};
  for (double v :
       {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
        std::numeric_limits<double>::quiet_NaN()})
    cases.emplace_back(v, 3);
  std::mt19937_64 rng(20261125);
  std::uniform_real_distribution<double> exponent(-8.0, 9.0);
  std::uniform_int_distribution<int> decimals(0, 9);
  for (int i = 0; i < 1'000'000; ++i) {
    const double sign = (rng() & 1) != 0 ? -1.0 : 1.0;
    cases.emplace_back(sign * std::pow(10.0, exponent(rng)), decimals(rng));
  }
  // Values on the recording's own grids: a tick's time, millimetres, newtons.
  for (int i = 0; i < 200'000; ++i) cases.emplace_back(i * 0.01, 3 + i % 3);
  for (int i = 0; i < 200'000; ++i) cases.emplace_back(i * 0.005 - 500.0, 2);
  std::size_t differ = 0;
  for (const auto& [v, d] : cases) {
    if (ours(v, d) != printf_of(v, d)) {
      if (++differ <= 5)
        ADD_FAILURE() << v << " at " << d << ": " << ours(v, d) << " vs " << printf_of(v, d);
    }
  }
  EXPECT_EQ(differ, 0u) << "of " << cases.size();
}

// A live run: every bus signal the nodes send, decoded by planter-can with the board, equals
// what the controller's telemetry reads on the next tick; every command the controller sends
// decodes to its telemetry within one count.
TEST(SignalTable, DecodeAndTelemetryAgreeOnEveryBusSignal) {
  sim::Scenario s =
      sim::load_scenario(std::string(PLANTER_SOURCE_DIR) + "/scenarios/zhangqiu-field.toml");
  s.plant.route.distance_m = 1.0;
  sim::LockstepRunner r(s);
  auto& listener = r.bus().add_endpoint(4096);
  const cantool::FrameDecoder decoder(&s.board.controller);
  while (r.time_s() < 8.0) r.step();
  ASSERT_EQ(r.controller().state(), SupervisorState::kRunning);
  hal::CanFrame f;
  while (listener.receive(f)) {
  }
  std::set<std::string> compared;
  for (int tick = 0; tick < 200; ++tick) {
    r.step();
    const Telemetry& t = r.controller().telemetry();
    std::map<std::string, double> measured;  // sent after this tick's read: next tick's values
    while (listener.receive(f)) {
      const cantool::DecodedFrame d = decoder.decode(f);
      for (const auto& v : d.values) {
        const SignalDecl* sig = find_signal(v.name);
        if (sig == nullptr) continue;
        EXPECT_EQ(sig->unit, v.unit) << v.name;
        const NodeConfig* node = decoder.node_config(d.node);
        ASSERT_NE(node, nullptr);
        if (sig->source == SignalSource::kController) {
          const double count = 1.0 / node->counts_per_unit;
          EXPECT_NEAR(v.value, t.*sig->commanded, count) << v.name << " at tick " << tick;
          compared.insert(std::string(v.name));
        } else {
          measured[std::string(v.name)] = v.value;
        }
      }
    }
    r.step();
    const Telemetry& next = r.controller().telemetry();
    for (const auto& [name, value] : measured) {
      EXPECT_DOUBLE_EQ(value, next.*find_signal(name)->measured) << name << " at tick " << tick;
      compared.insert(name);
    }
    while (listener.receive(f)) {
    }
  }
  std::size_t on_bus = 0;
  for (const SignalDecl& sig : kSignals) on_bus += sig.on_bus();
  EXPECT_EQ(compared.size(), on_bus) << "a bus signal was never seen on the bus";
}
