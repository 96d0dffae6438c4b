#include "firmware/io/signal_table.h"

namespace planter {

double bus_to_si(BusScale scale, const NodeConfig& node, double raw) {
  switch (scale) {
    case BusScale::kPerCount:
      return raw / node.counts_per_unit;
    case BusScale::kPerMilleRated:
      return raw * 1e-3 * node.rated_torque;
    case BusScale::kTared:
      return (raw - node.zero_counts) / node.counts_per_unit;
    case BusScale::kNone:
      break;
  }
  return raw;
}

double si_to_bus(BusScale scale, const NodeConfig& node, double si) {
  switch (scale) {
    case BusScale::kPerCount:
      return si * node.counts_per_unit;
    case BusScale::kPerMilleRated:
      return si / node.rated_torque * 1000.0;
    case BusScale::kTared:
      return si * node.counts_per_unit + node.zero_counts;
    case BusScale::kNone:
      break;
  }
  return si;
}

const SignalDecl* find_bus_signal(NodeRole role, std::uint16_t index, std::uint8_t sub) {
  for (const SignalDecl& s : kSignals) {
    if (s.on_bus() && s.role == role && s.index == index && s.sub == sub) return &s;
  }
  return nullptr;
}

}  // namespace planter
