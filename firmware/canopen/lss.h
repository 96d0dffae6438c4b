#pragma once
// Layer setting services (CiA 305): the command specifiers both sides use, and the slave's
// side of node-ID assignment (switch state, inquire, configure, store, fastscan).
#include <array>
#include <cstdint>

#include "planter/hal/can_bus.h"

namespace planter::canopen {

constexpr std::uint16_t kLssMasterCobId = 0x7E5;  // master -> slaves
constexpr std::uint16_t kLssSlaveCobId = 0x7E4;   // slave -> master
constexpr std::uint8_t kUnconfiguredNodeId = 0xFF;

namespace lss_cs {
constexpr std::uint8_t kSwitchGlobal = 0x04;
constexpr std::uint8_t kSwitchSelectiveVendor = 0x40;  // .. 0x43 serial
constexpr std::uint8_t kSwitchSelectiveReply = 0x44;
constexpr std::uint8_t kConfigureNodeId = 0x11;
constexpr std::uint8_t kConfigureBitTiming = 0x13;
constexpr std::uint8_t kActivateBitTiming = 0x15;
constexpr std::uint8_t kStore = 0x17;
constexpr std::uint8_t kFastscanReply = 0x4F;
constexpr std::uint8_t kFastscan = 0x51;
constexpr std::uint8_t kInquireVendor = 0x5A;  // .. 0x5D serial
constexpr std::uint8_t kInquireNodeId = 0x5E;
constexpr std::uint8_t kFastscanReset = 0x80;  // BitChecked value that starts a fastscan
}  // namespace lss_cs

// An LSS frame (master 0x7E5 or slave 0x7E4): command specifier, then a 32-bit value.
hal::CanFrame lss_frame(std::uint16_t cob_id, std::uint8_t cs, std::uint32_t value);

class LssSlave {
 public:
  // identity: vendor, product, revision, serial (0x1018:1-4).
  LssSlave(const std::array<std::uint32_t, 4>& identity, std::uint8_t node_id)
      : identity_(identity), active_id_(node_id), pending_id_(node_id), stored_id_(node_id) {}

  enum class Event : std::uint8_t { kNone, kHandled, kActivateNodeId };
  // kActivateNodeId: an unconfigured node got an ID and was switched back to waiting; the
  // device takes it at once (NMT reset communication), as CiA 305 asks.
  Event on_frame(const hal::CanFrame& frame, hal::CanBus& bus);

  [[nodiscard]] bool configuration_mode() const { return configuring_; }
  [[nodiscard]] std::uint8_t active_node_id() const { return active_id_; }
  [[nodiscard]] std::uint8_t pending_node_id() const { return pending_id_; }
  // NMT reset communication / power-on: the pending (or stored) ID becomes active.
  void reset_communication() { active_id_ = pending_id_; }
  void power_on() { pending_id_ = active_id_ = stored_id_; }

 private:
  void reply(std::uint8_t cs, std::uint32_t value, hal::CanBus& bus);
  std::array<std::uint32_t, 4> identity_;
  std::uint8_t active_id_;
  std::uint8_t pending_id_;
  std::uint8_t stored_id_;
  bool configuring_ = false;
  std::uint8_t selective_matched_ = 0;  // switch-selective parts matched so far
  std::uint8_t fastscan_pos_ = 0;
};

}  // namespace planter::canopen
