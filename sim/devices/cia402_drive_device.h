#pragma once
// A simulated CiA 402 drive (profile velocity or profile position). The plant model reads its
// commands and writes its actual values; the state machine is the firmware's own.
#include "firmware/canopen/cia402.h"
#include "sim/devices/canopen_device.h"

namespace planter::sim {

class Cia402DriveDevice final : public CanopenDevice {
 public:
  Cia402DriveDevice(const DeviceIdentity& identity, hal::CanBus& bus);

  [[nodiscard]] canopen::cia402::State state() const { return state_; }
  [[nodiscard]] bool enabled() const { return state_ == canopen::cia402::State::kOperationEnabled; }
  [[nodiscard]] bool quick_stopping() const {
    return state_ == canopen::cia402::State::kQuickStopActive;
  }
  // Not const: they read through the entry cache below.
  [[nodiscard]] std::int8_t mode();
  [[nodiscard]] std::int64_t target_velocity();
  [[nodiscard]] std::int64_t position_setpoint() const { return position_setpoint_; }
  [[nodiscard]] std::int64_t profile_velocity();

  void set_actual(std::int64_t position, std::int64_t velocity, std::int16_t torque_per_mille);
  // A drive fault (e.g. overcurrent): goes to fault and sends EMCY.
  void raise_fault(std::uint16_t error_code);

 protected:
  void on_rpdo() override;
  void on_reset() override;
  [[nodiscard]] std::uint32_t check_profile_write(const canopen::ObjectEntry& entry,
                                                  std::uint64_t value) const override;

 private:
  void publish_status();
  // The objects the plant reads and writes on every substep, found again only when the
  // dictionary's revision changes. A cache of where the entries are; the values always live
  // in the dictionary.
  struct HotObjects {
    canopen::ObjectEntry* position_actual = nullptr;
    canopen::ObjectEntry* velocity_actual = nullptr;
    canopen::ObjectEntry* torque_actual = nullptr;
    canopen::ObjectEntry* mode = nullptr;
    canopen::ObjectEntry* target_velocity = nullptr;
    canopen::ObjectEntry* profile_velocity = nullptr;
  };
  [[nodiscard]] const HotObjects& hot();
  HotObjects hot_{};
  std::uint64_t hot_revision_ = ~std::uint64_t{0};
  canopen::cia402::State state_ = canopen::cia402::State::kSwitchOnDisabled;
  std::uint16_t previous_controlword_ = 0;
  std::int64_t position_setpoint_ = 0;
  bool homing_ = false;
  bool homed_ = false;
  int homing_stalled_steps_ = 0;  // plant steps without the position falling
  std::int64_t last_position_ = 0;
};

class Cia404ForceSensor final : public CanopenDevice {
 public:
  Cia404ForceSensor(const DeviceIdentity& identity, hal::CanBus& bus);
  // Force in newtons; transmitted with one decimal (0x6132 = 1).
  void set_force_N(double force_N);
};

}  // namespace planter::sim
