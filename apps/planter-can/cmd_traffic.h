#pragma once
// Bus traffic: `monitor` (live decode with names, units and rates), `record` (a candump -L
// log, the tool's own frames included), `replay` (a log back onto the bus, timed), and
// `decode` (a log into the recording CSV of docs/recording-format.md).
#include <atomic>
#include <string>

#include "apps/planter-can/tool_context.h"

namespace planter::cantool {

struct TrafficOptions {
  double duration_s = 0.0;  // 0 = until interrupted
  bool raw = false;         // monitor: raw bytes beside the decode
  bool summary_only = false;
  double summary_every_s = 0.0;             // monitor: rate table this often (0 = at the end only)
  double speed = 1.0;                       // replay
  double max_gap_s = 10.0;                  // replay: longer silences in a log are shortened
  const std::atomic<bool>* stop = nullptr;  // set by SIGINT/SIGTERM
};

int run_monitor(ToolContext& ctx, const TrafficOptions& options);
int run_record(ToolContext& ctx, const std::string& path, const TrafficOptions& options);
int run_replay(ToolContext& ctx, const std::string& path, const TrafficOptions& options);
// No bus needed: reads the log, writes CSV to `out_path` (or stdout when empty).
int run_decode(const config::BoardConfig* board, const std::string& log_path,
               const std::string& out_path, std::ostream& out, std::ostream& err);

}  // namespace planter::cantool
