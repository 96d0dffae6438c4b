#include "config/board_checks.h"

#include <cmath>
#include <cstdio>

#include "config/board_keys.h"
#include "config/toml_section.h"
#include "planter/hal/can_frame.h"

namespace planter::config {

namespace {

// A disc drive's position must not wrap within an hour at full speed (a long field day's run
// between two power-ons would otherwise show a jump of the disc angle).
constexpr double kDiscPositionHorizonS = 3600.0;

struct Scale {
  const char* what;   // for the message
  double full_scale;  // the largest engineering value the object carries
  double resolution;  // one count must be at most this many units
  const char* unit;
};

std::string format(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

// The engineering range of an object a node maps, in the node's unit; false if unknown.
bool scale_of(const NodeConfig& n, std::uint16_t index, const ControllerConfig& c, Scale& s) {
  switch (n.role) {
    case NodeRole::kDiscDrive:
      if (index == 0x60FF || index == 0x606C) {
        s = {"disc speed", c.sigma.omega_max_radps, c.sigma.omega_max_radps / 1000.0, "rad/s"};
        return true;
      }
      if (index == 0x6064) {
        s = {"disc angle over an hour at omega_max",
             c.sigma.omega_max_radps * kDiscPositionHorizonS, 1e-3, "rad"};
        return true;
      }
      return false;
    case NodeRole::kRollerActuator:
      if (index == 0x607A || index == 0x6064) {
        s = {"clamp position", c.clamp.position_max_mm, 0.1, "mm"};
        return true;
      }
      return false;
    case NodeRole::kDepthActuator:
      if (index == 0x607A || index == 0x6064) {
        s = {"depth", std::max(std::fabs(c.depth.max_mm), std::fabs(c.depth.min_mm)), 0.1, "mm"};
        return true;
      }
      return false;
    case NodeRole::kForceSensor:
      if (index == 0x7130) {
        s = {"clamp force", c.supervisor.force_plausible_max_N, 1.0, "N"};
        return true;
      }
      return false;
  }
  return false;
}

}  // namespace

double planned_bus_load_pct(const ControllerConfig& c) {
  const double period_s = static_cast<double>(c.can.sync_period_ns) * 1e-9;
  double bits = hal::can_frame_bits(0);  // SYNC
  for (const NodeConfig& n : c.nodes) {
    for (const auto* maps : {&n.tpdo, &n.rpdo}) {
      for (const auto& m : *maps) {
        if (m.count > 0) bits += hal::can_frame_bits(m.total_bits() / 8);
      }
    }
    bits += hal::can_frame_bits(1) * period_s / (c.can.heartbeat_producer_ms * 1e-3);
  }
  return 100.0 * bits / (static_cast<double>(c.can.bitrate_bps) * period_s);
}

void check_node_scaling(TomlSection& node, const NodeConfig& n, const ControllerConfig& c) {
  const double cpu = n.counts_per_unit;
  for (const auto* maps : {&n.tpdo, &n.rpdo}) {
    for (const auto& m : *maps) {
      for (std::uint8_t i = 0; i < m.count; ++i) {
        Scale s{};
        if (!scale_of(n, m.entries[i].index, c, s)) continue;
        const double max_counts = std::ldexp(1.0, m.entries[i].bits - 1) - 1.0;
        const double counts = s.full_scale * cpu + std::fabs(n.zero_counts);
        if (counts > max_counts) {
          node.fail(key_in(kMachineKeys, "nodes.*.counts_per_unit"),
                    format(cpu) + " makes the " + s.what + " (" + format(s.full_scale) + " " +
                        s.unit + ") " + format(counts) + " counts, beyond the " +
                        std::to_string(m.entries[i].bits) + "-bit object's " + format(max_counts) +
                        "; allowed at most " +
                        format((max_counts - std::fabs(n.zero_counts)) / s.full_scale));
        }
        if (1.0 / cpu > s.resolution) {
          node.fail(key_in(kMachineKeys, "nodes.*.counts_per_unit"),
                    format(cpu) + " makes one count " + format(1.0 / cpu) + " " + s.unit + " of " +
                        s.what + "; the loops need at most " + format(s.resolution) +
                        " (allowed at least " + format(1.0 / s.resolution) + ")");
        }
      }
    }
  }
  if (n.profile_velocity_units_per_s * cpu > 4294967295.0) {
    node.fail(key_in(kMachineKeys, "nodes.*.profile_velocity"),
              "times counts_per_unit exceeds 0x6081's 32 bits");
  }
}

}  // namespace planter::config
