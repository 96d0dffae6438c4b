#pragma once
// The master's view of one CANopen node: boot script (identity check and configuration over
// SDO), heartbeat watch, PDO process values and, for drives, the CiA 402 state.
#include <array>
#include <cstdint>

#include "firmware/canopen/cia402.h"
#include "firmware/canopen/heartbeat_consumer.h"
#include "firmware/canopen/sdo_client.h"
#include "firmware/io/io_config.h"
#include "firmware/io/node_config_script.h"

namespace planter {

class NodeLink {
 public:
  enum class BootState : std::uint8_t { kIdle, kRunning, kConfigured, kFailed };
  static constexpr std::size_t kMaxObjects = 24;

  NodeLink(const NodeConfig& config, const CanConfig& can);

  // Boot: builds nothing new (the script was built in the constructor); just (re)starts it.
  void start_boot(std::int64_t now_ns, hal::CanBus& bus);
  void step_boot(std::int64_t now_ns, hal::CanBus& bus);
  [[nodiscard]] BootState boot_state() const { return boot_state_; }
  // CiA 302-2 style error letter of a failed boot ('B' no answer, 'C' wrong profile, ...).
  [[nodiscard]] char boot_error() const { return boot_error_; }

  // Frame dispatch; true when the frame belonged to this node.
  bool on_frame(const hal::CanFrame& frame, std::int64_t now_ns, hal::CanBus& bus);

  // Process values, by slot (slots are found once at init with slot()).
  [[nodiscard]] int slot(std::uint16_t index, std::uint8_t sub = 0) const;
  [[nodiscard]] std::int64_t value(int slot) const;
  void set_value(int slot, std::int64_t value);
  // Sends every configured RPDO with the current values.
  void send_rpdos(hal::CanBus& bus);

  [[nodiscard]] const NodeConfig& config() const { return cfg_; }
  canopen::HeartbeatConsumer& heartbeat() { return heartbeat_; }
  [[nodiscard]] const canopen::HeartbeatConsumer& heartbeat() const { return heartbeat_; }
  // When the stalest of the node's mapped TPDOs last arrived: every process value must keep
  // coming, not just one of the node's PDOs (a TPDO the node never sends leaves its values
  // at 0, which must fault as stale, not read as a standing disc).
  [[nodiscard]] std::int64_t last_tpdo_ns() const;
  [[nodiscard]] std::uint16_t last_emcy_code() const { return last_emcy_code_; }
  [[nodiscard]] std::uint32_t emcy_count() const { return emcy_count_; }
  [[nodiscard]] std::uint32_t bad_pdo_count() const { return bad_pdo_; }
  void clear_emcy() { last_emcy_code_ = 0; }

  // CiA 402 helpers (drives only): steers the drive towards `wanted` via the controlword slot.
  void drive_towards(canopen::cia402::State wanted);
  [[nodiscard]] canopen::cia402::State drive_state() const;
  // Profile position: a new target is taken on a rising edge of controlword bit 4.
  void set_position_target(std::int64_t counts);

 private:
  struct Object {
    std::uint16_t index;
    std::uint8_t sub;
    std::uint8_t bits;
    std::int64_t value;
  };
  int add_object(std::uint16_t index, std::uint8_t sub, std::uint8_t bits);
  void start_step(std::int64_t now_ns, hal::CanBus& bus);

  NodeConfig cfg_;
  std::uint16_t heartbeat_ms_;
  canopen::SdoClient sdo_;
  canopen::HeartbeatConsumer heartbeat_;
  std::array<Object, kMaxObjects> objects_{};
  std::size_t object_count_ = 0;
  std::array<std::array<int, canopen::PdoMapping::kMaxEntries>, 4> tpdo_slots_{};
  std::array<std::array<int, canopen::PdoMapping::kMaxEntries>, 4> rpdo_slots_{};
  NodeConfigScript script_;
  std::size_t step_ = 0;
  std::array<std::uint8_t, 8> read_buffer_{};
  BootState boot_state_ = BootState::kIdle;
  char boot_error_ = 0;
  std::array<std::int64_t, 4> last_tpdo_ns_{};  // per TPDO
  std::uint16_t last_emcy_code_ = 0;
  std::uint32_t emcy_count_ = 0;
  std::uint32_t bad_pdo_ = 0;
  int controlword_slot_ = -1;
  int statusword_slot_ = -1;
  int target_position_slot_ = -1;
  bool fault_reset_phase_ = false;
  bool setpoint_toggle_ = false;
  std::int64_t pending_position_ = 0;
};

}  // namespace planter
