// The console names its values by their recording columns (issue 29, item 2): every name the
// page reads from /api/state and /api/history is a column of the signal table or of the
// simulator's truth, or one of the few the console adds (time, state, lists, the recording).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "console/live_sample.h"
#include "firmware/io/signal_table.h"
#include "sim/plant/truth_columns.h"

using namespace planter;

namespace {

bool is_truth_column(std::string_view name) {
  for (const auto& c : sim::kTruthColumns)
    if (c.column == name) return true;
  return false;
}

}  // namespace

TEST(ConsoleSignalNames, ThePageReadsOnlyTheSignalTablesNames) {
  std::ifstream in(std::string(PLANTER_SOURCE_DIR) + "/console/console_page.html");
  ASSERT_TRUE(in) << "console/console_page.html not found";
  std::stringstream page;
  page << in.rdbuf();
  const std::string text = page.str();
  // What the console adds that is not a signal: the sample's time, the supervisor's words, the
  // planting block and its counters that are not recording columns, the recording's name.
  const std::set<std::string> the_consoles_own = {
      "t_s",      "state",     "faults",   "warnings",
      "planting", "recording", "spacings", "empty_clamps_in_row",
      "gnss"};
  // s.NAME (a state), h.NAME (the history), p.NAME (its planting block), rows(["NAME", ...]).
  std::set<std::string> names;
  const std::regex field(R"(\b[shp]\.([a-z_]+)\b)");
  for (std::sregex_iterator m(text.begin(), text.end(), field), end; m != end; ++m)
    names.insert((*m)[1]);
  const std::regex rows(R"(rows\(\[([^\]]*)\]\))");
  const std::regex quoted(R"re("([a-z_]+)")re");
  for (std::sregex_iterator m(text.begin(), text.end(), rows), end; m != end; ++m) {
    const std::string list = (*m)[1];
    for (std::sregex_iterator q(list.begin(), list.end(), quoted); q != end; ++q)
      names.insert((*q)[1]);
  }
  ASSERT_GT(names.size(), 15u) << "the page's names were not found: has its script changed form?";
  for (const std::string& name : names) {
    const bool known =
        find_signal(name) != nullptr || is_truth_column(name) || the_consoles_own.count(name) > 0;
    EXPECT_TRUE(known) << "the console page reads '" << name
                       << "', which is neither a recording column nor the console's own";
  }
  // The one truth column the console shows is the simulator's own name for it.
  EXPECT_TRUE(is_truth_column(console::kTrueSigmaKey));
  // And the state the server sends carries those names.
  const std::string state = console::to_json(console::LiveSample{});
  for (const char* column : {"v_wheel", "sigma", "omega", "clamp_force", "clamp_force_cmd",
                             "depth_mm", "depth_target_mm", "seedlings_per_m", "true_sigma"})
    EXPECT_NE(state.find(std::string("\"") + column + "\""), std::string::npos) << column;
}
