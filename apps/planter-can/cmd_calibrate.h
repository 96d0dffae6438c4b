#pragma once
// `calibrate`: the three calibrations a technician does at commissioning, each shown as
// before/after and written back into the board file (atomically, FILE.bak kept):
//   force       zero and span of the clamp force sensor with a known weight
//   soil-wheel  encoder counts per metre over a measured distance -> effective wheel radius
//   depth       homing of the opener actuator and its travel to the upper end stop
#include <istream>
#include <string>

#include "apps/planter-can/tool_context.h"

namespace planter::cantool {

struct CalibrateOptions {
  std::string what;             // force | soil-wheel | depth
  double known_N = 0.0;         // force
  double distance_m = 0.0;      // soil-wheel
  int samples = 20;             // force: readings averaged per step
  double still_s = 2.0;         // soil-wheel: the wheel is at rest this long at the end
  double max_wait_s = 600.0;    // soil-wheel: give up after this
  double ready_after_s = -1.0;  // scripts: wait this long instead of asking for Enter
  bool write = true;            // write the result into the board file
  const char* not_written_because = "--no-write";  // said when write is false
};

int run_calibrate(ToolContext& ctx, const CalibrateOptions& options, std::istream& in);

}  // namespace planter::cantool
