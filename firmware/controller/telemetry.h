#pragma once
// What the machine did in its last tick: the process image read (MachineState), the command
// written (MachineCommand), and the supervisor's verdict. SI units (mm where named); the
// recording columns are declared in firmware/io/signal_table.h.
#include <cstdint>

#include "firmware/io/process_image.h"
#include "firmware/sensing/planting_monitor.h"
#include "firmware/supervisor/supervisor.h"

namespace planter {

struct Telemetry : MachineState, MachineCommand {
  std::int64_t time_ns = 0;
  SupervisorState state = SupervisorState::kBoot;
  std::uint32_t faults = 0;  // latched, and seen this tick
  std::uint32_t overruns = 0;
  std::uint32_t warnings = 0;  // warning:: bits
  PlantingFigures planting;    // the planting monitor (zeros when no photo-eye is fitted)
};

}  // namespace planter
