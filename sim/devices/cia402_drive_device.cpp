#include "sim/devices/cia402_drive_device.h"

#include <algorithm>
#include <cmath>

#include "firmware/canopen/profile_objects.h"

namespace planter::sim {

namespace c402 = canopen::cia402;

Cia402DriveDevice::Cia402DriveDevice(const DeviceIdentity& identity, hal::CanBus& bus)
    : CanopenDevice(identity, bus) {
  // Every object of the profile's table (firmware/canopen/profile_objects.h), so what the
  // loader accepts in a mapping the simulated drive serves.
  for (const canopen::ProfileObject& p : canopen::profile_objects(402)) {
    std::uint64_t value = 0;
    if (p.index == c402::kStatusword) value = c402::encode_state(state_);
    if (p.index == c402::kSupportedModes) value = (1u << 0) | (1u << 2) | (1u << 5);
    od().add(p.index, p.sub, p.size, p.access, value);
  }
}

std::uint32_t Cia402DriveDevice::check_profile_write(const canopen::ObjectEntry& entry,
                                                     std::uint64_t value) const {
  if (entry.index != c402::kModesOfOperation) return 0;
  // CiA 402 6.2.x: 0x6502 bit (mode - 1) says which positive modes the drive has; 0 = none.
  const auto mode = static_cast<std::int8_t>(value);
  if (mode == 0) return 0;
  const auto supported = od().get(c402::kSupportedModes, 0);
  if (mode > 0 && mode <= 32 && (supported & (1ull << (mode - 1))) != 0) return 0;
  return canopen::abort_code::kValueRange;
}

// All six are added by the constructor, so none is null.
const Cia402DriveDevice::HotObjects& Cia402DriveDevice::hot() {
  auto& o = od();
  if (o.revision() != hot_revision_) {
    hot_ = {o.find(c402::kPositionActual, 0), o.find(c402::kVelocityActual, 0),
            o.find(c402::kTorqueActual, 0),   o.find(c402::kModesOfOperation, 0),
            o.find(c402::kTargetVelocity, 0), o.find(c402::kProfileVelocity, 0)};
    hot_revision_ = o.revision();
  }
  return hot_;
}

std::int8_t Cia402DriveDevice::mode() { return static_cast<std::int8_t>(hot().mode->value); }

std::int64_t Cia402DriveDevice::target_velocity() {
  return canopen::sign_extend(hot().target_velocity->value, 32);
}

std::int64_t Cia402DriveDevice::profile_velocity() {
  return static_cast<std::int64_t>(hot().profile_velocity->value);
}

void Cia402DriveDevice::on_rpdo() {
  auto& o = od();
  const auto cw = static_cast<std::uint16_t>(o.get(c402::kControlword, 0));
  state_ = c402::apply_controlword(state_, cw, previous_controlword_);
  const bool new_setpoint = (cw & c402::controlword::kNewSetPoint) != 0 &&
                            (previous_controlword_ & c402::controlword::kNewSetPoint) == 0;
  if (new_setpoint && enabled()) {
    if (mode() == c402::kModeHoming) {
      // Homing on the lower end stop: drive down until the actuator stops there.
      homing_ = true;
      homed_ = false;
      position_setpoint_ = -(std::int64_t{1} << 40);
    } else {
      position_setpoint_ = o.get_signed(c402::kTargetPosition, 0);
    }
  }
  previous_controlword_ = cw;
  o.set(c402::kModesDisplay, 0, o.get(c402::kModesOfOperation, 0));
  publish_status();
}

void Cia402DriveDevice::on_reset() {
  state_ = c402::State::kSwitchOnDisabled;
  previous_controlword_ = 0;
  publish_status();
}

void Cia402DriveDevice::publish_status() {
  std::uint16_t sw = c402::encode_state(state_);
  sw |= 0x0010;  // voltage enabled
  if (homed_ && mode() == c402::kModeHoming)
    sw |= c402::statusword::kTargetReached | c402::statusword::kSetPointAcknowledge;
  od().set(c402::kStatusword, 0, sw);
}

void Cia402DriveDevice::set_actual(std::int64_t position, std::int64_t velocity,
                                   std::int16_t torque) {
  auto& o = od();
  const HotObjects& objects = hot();
  o.store(*objects.position_actual, static_cast<std::uint64_t>(position));
  o.store(*objects.velocity_actual, static_cast<std::uint64_t>(velocity));
  o.store(*objects.torque_actual, static_cast<std::uint64_t>(static_cast<std::int64_t>(torque)));
  if (homing_) {
    // The end stop is reached when the position stops falling.
    homing_stalled_steps_ = position >= last_position_ ? homing_stalled_steps_ + 1 : 0;
    if (homing_stalled_steps_ >= 50) {
      homing_ = false;
      homed_ = true;
      position_setpoint_ = position;
      publish_status();
    }
  }
  last_position_ = position;
  if (mode() == c402::kModeProfilePosition && std::llabs(position - position_setpoint_) < 20) {
    o.set(c402::kStatusword, 0, o.get(c402::kStatusword, 0) | c402::statusword::kTargetReached);
  }
}

void Cia402DriveDevice::raise_fault(std::uint16_t error_code) {
  state_ = c402::State::kFault;
  od().set(c402::kErrorCode, 0, error_code);
  publish_status();
  send_emcy(error_code, 0x01);
}

Cia404ForceSensor::Cia404ForceSensor(const DeviceIdentity& identity, hal::CanBus& bus)
    : CanopenDevice(identity, bus) {
  for (const canopen::ProfileObject& p : canopen::profile_objects(404)) {
    std::uint64_t value = 0;
    if (p.index == 0x7130 && p.sub == 0) value = 1;  // one channel
    if (p.index == 0x6131) value = 0x00210000;       // unit: newton (CiA 303-2)
    if (p.index == 0x6132) value = 1;                // one decimal: the value in 0.1 N
    od().add(p.index, p.sub, p.size, p.access, value);
  }
}

void Cia404ForceSensor::set_force_N(double force_N) {
  const double counts = std::clamp(std::round(force_N * 10.0), -32768.0, 32767.0);
  od().set(0x7130, 1, static_cast<std::uint64_t>(static_cast<std::int64_t>(counts)));
}

}  // namespace planter::sim
