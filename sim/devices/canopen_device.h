#pragma once
// A simulated CANopen slave: object dictionary, SDO server, NMT, heartbeat producer and a
// PDO engine driven by its own communication objects (so the master's configuration is real).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/lss.h"
#include "firmware/canopen/pdo.h"
#include "planter/hal/can_bus.h"
#include "sim/devices/object_dictionary.h"
#include "sim/devices/sdo_server.h"

namespace planter::sim {

struct DeviceIdentity {
  std::uint8_t node_id = 1;       // 0xFF: unconfigured, waits for an ID over LSS
  std::uint32_t device_type = 0;  // 0x1000
  std::uint32_t vendor_id = 0;
  std::uint32_t product_code = 0;
  std::uint32_t revision = 1;
  std::uint32_t serial = 1;
  std::string name;
};

class CanopenDevice : private canopen::SdoWriteRules {
 public:
  static constexpr std::uint8_t kErrorHistoryDepth = 8;
  CanopenDevice(const DeviceIdentity& identity, hal::CanBus& bus);
  virtual ~CanopenDevice() = default;

  // Power-on: sends the boot-up frame.
  void power_on(std::int64_t now_ns);
  // Handles every pending frame, then produces heartbeats that are due.
  void process(std::int64_t now_ns);

  [[nodiscard]] canopen::NmtState nmt_state() const { return nmt_; }
  [[nodiscard]] std::uint8_t node_id() const { return identity_.node_id; }
  [[nodiscard]] bool unconfigured() const {
    return identity_.node_id == canopen::kUnconfiguredNodeId;
  }
  canopen::ObjectDictionary& od() { return od_; }
  [[nodiscard]] const canopen::ObjectDictionary& od() const { return od_; }
  // Sends an EMCY frame (code 0 = error reset).
  void send_emcy(std::uint16_t code, std::uint8_t error_register);

 protected:
  // After an RPDO updated the dictionary.
  virtual void on_rpdo() {}
  // Restores the application's defaults on reset node.
  virtual void on_reset() {}
  // The profile's own refusals of an SDO write (0 accepts), after the CiA 301 rules.
  [[nodiscard]] virtual std::uint32_t check_profile_write(const canopen::ObjectEntry& /*entry*/,
                                                          std::uint64_t /*value*/) const {
    return 0;
  }

 private:
  // CiA 301's rules for the communication objects, then check_profile_write.
  [[nodiscard]] std::uint32_t check_write(const canopen::ObjectEntry& entry,
                                          std::uint64_t value) const override;
  [[nodiscard]] std::uint32_t check_mapping_write(const canopen::ObjectEntry& entry,
                                                  std::uint64_t value) const;
  [[nodiscard]] std::uint32_t check_mapped_object(std::uint32_t mapping_value, bool receive) const;
  void handle(const hal::CanFrame& frame, std::int64_t now_ns);
  void reset_communication(std::int64_t now_ns);
  void on_sync();
  [[nodiscard]] canopen::PdoMapping mapping(std::uint16_t map_index) const;
  // The PDOs and the heartbeat period as entry pointers, resolved again only when the
  // dictionary's revision changes (a configuration write), not on every frame and SYNC.
  void resolve_if_changed();
  void send_heartbeat(std::uint8_t state);
  void after_sdo_write();
  void set_node_id(std::uint8_t node_id);

  DeviceIdentity identity_;
  hal::CanBus& bus_;
  canopen::ObjectDictionary od_;
  canopen::SdoServer sdo_;
  canopen::LssSlave lss_;
  std::uint32_t sdo_writes_seen_ = 0;
  std::uint8_t error_count_ = 0;
  // Communication objects saved by 0x1010:1 = "save"; restored on reset communication.
  std::vector<canopen::ObjectEntry> stored_comm_;
  canopen::NmtState nmt_ = canopen::NmtState::kPreOperational;
  std::int64_t next_heartbeat_ns_ = 0;
  std::uint32_t sync_count_ = 0;

  struct ResolvedPdo {
    bool valid = false;
    std::uint16_t cob_id = 0;
    std::uint64_t transmission_type = 0;
    canopen::PdoMapping mapping;
    // The mapped objects; nullptr where the device lacks one (reads 0, writes nothing).
    std::array<canopen::ObjectEntry*, canopen::PdoMapping::kMaxEntries> objects{};
  };
  std::array<ResolvedPdo, 4> rpdos_{};
  std::array<ResolvedPdo, 4> tpdos_{};
  const canopen::ObjectEntry* heartbeat_period_ms_ = nullptr;
  std::uint64_t resolved_revision_ = ~std::uint64_t{0};
};

}  // namespace planter::sim
