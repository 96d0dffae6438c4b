#include "apps/planter-can/object_names.h"

#include <array>
#include <cstdio>

namespace planter::cantool {
namespace {

constexpr std::array kObjects{
    ObjectInfo{0x1000, 0, "device type", "x32", ""},
    ObjectInfo{0x1001, 0, "error register", "x8", ""},
    ObjectInfo{0x1003, 0, "error history count", "u8", ""},
    ObjectInfo{0x1003, kAnySub, "error history", "x32", ""},
    ObjectInfo{0x1005, 0, "SYNC COB-ID", "x32", ""},
    ObjectInfo{0x1006, 0, "SYNC period", "u32", "us"},
    ObjectInfo{0x1008, 0, "device name", "vs", ""},
    ObjectInfo{0x1009, 0, "hardware version", "vs", ""},
    ObjectInfo{0x100A, 0, "software version", "vs", ""},
    ObjectInfo{0x1010, kAnySub, "store parameters", "x32", ""},
    ObjectInfo{0x1011, kAnySub, "restore defaults", "x32", ""},
    ObjectInfo{0x1016, kAnySub, "consumer heartbeat", "x32", ""},
    ObjectInfo{0x1017, 0, "producer heartbeat", "u16", "ms"},
    ObjectInfo{0x1018, 0, "identity entries", "u8", ""},
    ObjectInfo{0x1018, 1, "vendor-ID", "x32", ""},
    ObjectInfo{0x1018, 2, "product code", "x32", ""},
    ObjectInfo{0x1018, 3, "revision", "x32", ""},
    ObjectInfo{0x1018, 4, "serial number", "x32", ""},
    ObjectInfo{0x603F, 0, "error code", "x16", ""},
    ObjectInfo{0x6040, 0, "controlword", "x16", ""},
    ObjectInfo{0x6041, 0, "statusword", "x16", ""},
    ObjectInfo{0x6060, 0, "mode of operation", "i8", ""},
    ObjectInfo{0x6061, 0, "mode display", "i8", ""},
    ObjectInfo{0x6064, 0, "position actual", "i32", "counts"},
    ObjectInfo{0x606C, 0, "velocity actual", "i32", "counts/s"},
    ObjectInfo{0x6077, 0, "torque actual", "i16", "per mille"},
    ObjectInfo{0x607A, 0, "target position", "i32", "counts"},
    ObjectInfo{0x6081, 0, "profile velocity", "u32", "counts/s"},
    ObjectInfo{0x6083, 0, "profile acceleration", "u32", "counts/s2"},
    ObjectInfo{0x6098, 0, "homing method", "i8", ""},
    ObjectInfo{0x60FF, 0, "target velocity", "i32", "counts/s"},
    ObjectInfo{0x6502, 0, "supported drive modes", "x32", ""},
    ObjectInfo{0x6126, kAnySub, "scaling factor", "r32", ""},
    ObjectInfo{0x6127, kAnySub, "scaling offset", "r32", ""},
    ObjectInfo{0x6131, kAnySub, "physical unit", "x32", ""},
    ObjectInfo{0x6132, kAnySub, "decimal digits", "u8", ""},
    ObjectInfo{0x6138, kAnySub, "tare zero", "i32", ""},
    ObjectInfo{0x6139, kAnySub, "autotare", "x32", ""},
    ObjectInfo{0x6150, kAnySub, "sensor status", "x8", ""},
    ObjectInfo{0x7130, 0, "process values", "u8", ""},
    ObjectInfo{0x7130, kAnySub, "force process value", "i16", "0.1 N"},
};

}  // namespace

const ObjectInfo* find_object(std::uint16_t index, std::uint8_t sub) {
  const ObjectInfo* any = nullptr;
  for (const auto& o : kObjects) {
    if (o.index != index) continue;
    if (o.sub == sub) return &o;
    if (o.sub == kAnySub) any = &o;
  }
  if (any) return any;
  // PDO parameters, by range.
  static constexpr ObjectInfo kRpdoComm{0x1400, kAnySub, "RPDO communication", "x32", ""};
  static constexpr ObjectInfo kRpdoMap{0x1600, kAnySub, "RPDO mapping", "x32", ""};
  static constexpr ObjectInfo kTpdoComm{0x1800, kAnySub, "TPDO communication", "x32", ""};
  static constexpr ObjectInfo kTpdoMap{0x1A00, kAnySub, "TPDO mapping", "x32", ""};
  if (index >= 0x1400 && index <= 0x15FF) return &kRpdoComm;
  if (index >= 0x1600 && index <= 0x17FF) return &kRpdoMap;
  if (index >= 0x1800 && index <= 0x19FF) return &kTpdoComm;
  if (index >= 0x1A00 && index <= 0x1BFF) return &kTpdoMap;
  return nullptr;
}

std::string_view object_label(std::uint16_t index, std::uint8_t sub, char* buf, std::size_t size) {
  const ObjectInfo* o = find_object(index, sub);
  if (o != nullptr && o->sub != kAnySub) return o->name;
  const int n = o ? std::snprintf(buf, size, "%.*s %04X:%02X", static_cast<int>(o->name.size()),
                                  o->name.data(), index, sub)
                  : std::snprintf(buf, size, "%04X:%02X", index, sub);
  return std::string_view(buf,
                          n > 0 ? std::min<std::size_t>(static_cast<std::size_t>(n), size - 1) : 0);
}

const char* emcy_code_text(std::uint16_t code) {
  if (code == 0x0000) return "error reset or no error";
  if (code == 0x1000) return "generic error";
  if (code == 0x8110) return "CAN overrun (objects lost)";
  if (code == 0x8120) return "CAN in error passive mode";
  if (code == 0x8130) return "life guard or heartbeat error";
  if (code == 0x8140) return "recovered from bus off";
  if (code == 0x8210) return "PDO not processed due to length error";
  if (code == 0x8611) return "following error";
  switch (code & 0xFF00) {
    case 0x2100:
      return "current, device input side";
    case 0x2200:
      return "current inside the device";
    case 0x2300:
      return "current, device output side (overcurrent)";
    case 0x3100:
      return "mains voltage";
    case 0x3200:
      return "voltage inside the device";
    case 0x3300:
      return "output voltage";
    case 0x4200:
      return "device temperature";
    case 0x4300:
      return "drive temperature";
    case 0x5000:
    case 0x5100:
    case 0x5200:
    case 0x5300:
    case 0x5400:
    case 0x5500:
      return "device hardware";
    case 0x6000:
    case 0x6100:
    case 0x6200:
    case 0x6300:
      return "device software";
    case 0x7000:
    case 0x7100:
      return "additional modules / motor";
    case 0x7300:
      return "sensor";
    case 0x8000:
    case 0x8100:
      return "monitoring / communication";
    case 0x8200:
      return "protocol error";
    case 0x8300:
      return "torque control";
    case 0x8400:
      return "velocity speed controller";
    case 0x8500:
      return "position controller";
    case 0x8600:
      return "positioning controller";
    case 0x9000:
      return "external error";
    case 0xF000:
      return "additional functions";
    case 0xFF00:
      return "device specific";
    default:
      return "unknown error class";
  }
}

const char* nmt_state_name(std::uint8_t state) {
  switch (state) {
    case 0x00:
      return "boot-up";
    case 0x04:
      return "stopped";
    case 0x05:
      return "operational";
    case 0x7F:
      return "pre-operational";
    case 0xFF:
      return "-";
    default:
      return "invalid state";
  }
}

const char* device_profile_text(std::uint32_t device_type) {
  switch (device_type & 0xFFFF) {
    case 0:
      return "no profile";
    case 401:
      return "CiA 401 generic I/O";
    case 402:
      return "CiA 402 drive";
    case 404:
      return "CiA 404 measuring device";
    case 406:
      return "CiA 406 encoder";
    case 418:
      return "CiA 418 battery";
    default:
      return "other profile";
  }
}

}  // namespace planter::cantool
