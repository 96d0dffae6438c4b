#include "firmware/io/node_config_script.h"

#include "firmware/canopen/cia402.h"
#include "firmware/canopen/cob_id.h"

namespace planter {

void NodeConfigScript::add(const ConfigStep& step) {
  if (count < kMaxSteps) {
    steps[count++] = step;
  } else {
    overflow = true;
  }
}

void build_node_config_script(const NodeConfig& cfg, std::uint16_t heartbeat_ms,
                              NodeConfigScript& out) {
  out.count = 0;
  out.overflow = false;
  // Identity first (CiA 302-2): no answer = B, wrong profile = C, wrong vendor = D, product = M.
  out.add({false, 0x1000, 0, 4, cfg.profile, 0xFFFF, 'C'});
  if (cfg.vendor_id != 0) out.add({false, 0x1018, 1, 4, cfg.vendor_id, 0xFFFFFFFF, 'D'});
  if (cfg.product_code != 0) out.add({false, 0x1018, 2, 4, cfg.product_code, 0xFFFFFFFF, 'M'});
  if (cfg.profile == 402) {
    const bool velocity = cfg.role == NodeRole::kDiscDrive;
    out.add({true, canopen::cia402::kModesOfOperation, 0, 1,
             static_cast<std::uint32_t>(velocity ? canopen::cia402::kModeProfileVelocity
                                                 : canopen::cia402::kModeProfilePosition),
             0, 'J'});
    if (!velocity && cfg.profile_velocity_units_per_s > 0) {
      out.add({true, canopen::cia402::kProfileVelocity, 0, 4,
               static_cast<std::uint32_t>(cfg.profile_velocity_units_per_s * cfg.counts_per_unit),
               0, 'J'});
    }
  }
  // SYNC consumer: the TPDOs below are sent on every SYNC (COB-ID 0x80, CiA 301).
  out.add({true, 0x1005, 0, 4, canopen::kSyncCobId, 0, 'J'});
  auto configure = [&out](std::uint16_t comm, std::uint16_t map, std::uint16_t cob,
                          const canopen::PdoMapping& m, std::uint8_t transmission,
                          bool node_transmits) {
    out.add({true, comm, 1, 4, 0x80000000u | cob, 0, 'J'});
    if (m.count == 0) return;  // left invalid
    // Every object a TPDO maps must exist on the node: a device that accepts any mapping would
    // otherwise send zeros for it all run long (a standing disc, sigma 0, and no fault).
    if (node_transmits) {
      for (std::uint8_t i = 0; i < m.count; ++i) {
        out.add({false, m.entries[i].index, m.entries[i].sub,
                 static_cast<std::uint8_t>(m.entries[i].bits / 8), 0, 0, 'J'});
      }
    }
    out.add({true, map, 0, 1, 0, 0, 'J'});
    for (std::uint8_t i = 0; i < m.count; ++i) {
      out.add(
          {true, map, static_cast<std::uint8_t>(i + 1), 4, m.entries[i].mapping_value(), 0, 'J'});
    }
    out.add({true, map, 0, 1, m.count, 0, 'J'});
    out.add({true, comm, 2, 1, transmission, 0, 'J'});
    out.add({true, comm, 1, 4, cob, 0, 'J'});
  };
  for (std::uint16_t k = 0; k < 4; ++k) {
    configure(static_cast<std::uint16_t>(0x1800 + k), static_cast<std::uint16_t>(0x1A00 + k),
              static_cast<std::uint16_t>(canopen::kTpdoBase[k] + cfg.node_id), cfg.tpdo[k], 1,
              true);
    configure(static_cast<std::uint16_t>(0x1400 + k), static_cast<std::uint16_t>(0x1600 + k),
              static_cast<std::uint16_t>(canopen::kRpdoBase[k] + cfg.node_id), cfg.rpdo[k], 255,
              false);
  }
  // Heartbeat last, so its watch starts from a configured node.
  out.add({true, 0x1017, 0, 2, heartbeat_ms, 0, 'K'});
}

}  // namespace planter
