#include "firmware/canopen/profile_objects.h"

#include <array>

namespace planter::canopen {
namespace {

using A = Access;
// CiA 402 (IEC 61800-7-201), the objects of the profile position and profile velocity modes
// and their common ones: index, sub-index, bytes, access.
constexpr std::array kCia402{
    ProfileObject{0x603F, 0, 2, A::kReadOnly},   // error code
    ProfileObject{0x6040, 0, 2, A::kReadWrite},  // controlword
    ProfileObject{0x6041, 0, 2, A::kReadOnly},   // statusword
    ProfileObject{0x605A, 0, 2, A::kReadWrite},  // quick stop option code
    ProfileObject{0x6060, 0, 1, A::kReadWrite},  // modes of operation
    ProfileObject{0x6061, 0, 1, A::kReadOnly},   // modes of operation display
    ProfileObject{0x6062, 0, 4, A::kReadOnly},   // position demand value
    ProfileObject{0x6063, 0, 4, A::kReadOnly},   // position actual internal value
    ProfileObject{0x6064, 0, 4, A::kReadOnly},   // position actual value
    ProfileObject{0x6065, 0, 4, A::kReadWrite},  // following error window
    ProfileObject{0x6067, 0, 4, A::kReadWrite},  // position window
    ProfileObject{0x606B, 0, 4, A::kReadOnly},   // velocity demand value
    ProfileObject{0x606C, 0, 4, A::kReadOnly},   // velocity actual value
    ProfileObject{0x6071, 0, 2, A::kReadWrite},  // target torque
    ProfileObject{0x6072, 0, 2, A::kReadWrite},  // max torque
    ProfileObject{0x6074, 0, 2, A::kReadOnly},   // torque demand
    ProfileObject{0x6077, 0, 2, A::kReadOnly},   // torque actual value
    ProfileObject{0x6078, 0, 2, A::kReadOnly},   // current actual value
    ProfileObject{0x6079, 0, 4, A::kReadOnly},   // DC link circuit voltage
    ProfileObject{0x607A, 0, 4, A::kReadWrite},  // target position
    ProfileObject{0x607C, 0, 4, A::kReadWrite},  // home offset
    ProfileObject{0x6081, 0, 4, A::kReadWrite},  // profile velocity
    ProfileObject{0x6083, 0, 4, A::kReadWrite},  // profile acceleration
    ProfileObject{0x6084, 0, 4, A::kReadWrite},  // profile deceleration
    ProfileObject{0x6085, 0, 4, A::kReadWrite},  // quick stop deceleration
    ProfileObject{0x6086, 0, 2, A::kReadWrite},  // motion profile type
    ProfileObject{0x60F4, 0, 4, A::kReadOnly},   // following error actual value
    ProfileObject{0x60FD, 0, 4, A::kReadOnly},   // digital inputs
    ProfileObject{0x60FF, 0, 4, A::kReadWrite},  // target velocity
    ProfileObject{0x6502, 0, 4, A::kConst},      // supported drive modes
};
// CiA 404 (measuring devices), the analogue input function block of channel 1: what the force
// sensor serves.
constexpr std::array kCia404{
    ProfileObject{0x6131, 1, 4, A::kReadWrite},  // AI physical unit (CiA 303-2)
    ProfileObject{0x6132, 1, 1, A::kReadWrite},  // AI decimal digits
    ProfileObject{0x6138, 1, 4, A::kWriteOnly},  // AI tare zero
    ProfileObject{0x6150, 1, 1, A::kReadOnly},   // AI status
    ProfileObject{0x7130, 0, 1, A::kConst},      // AI input process value: highest sub-index
    ProfileObject{0x7130, 1, 2, A::kReadOnly},   // AI input process value, channel 1
};

bool readable(Access a) { return a != Access::kWriteOnly; }
bool writable(Access a) { return a == Access::kReadWrite || a == Access::kWriteOnly; }

}  // namespace

std::span<const ProfileObject> profile_objects(std::uint16_t profile) {
  if (profile == 402) return kCia402;
  if (profile == 404) return kCia404;
  return {};
}

const ProfileObject* find_profile_object(std::uint16_t profile, std::uint16_t index,
                                         std::uint8_t sub) {
  for (const ProfileObject& o : profile_objects(profile))
    if (o.index == index && o.sub == sub) return &o;
  return nullptr;
}

MappingVerdict check_mapping(std::uint16_t profile, std::uint16_t index, std::uint8_t sub,
                             std::uint8_t bits, bool tpdo) {
  if (index < 0x1000 || (index >= 0x2000 && index < 0x6000)) return {MappingCheck::kUnchecked};
  if (index < 0x2000) return {MappingCheck::kCommunication};
  const ProfileObject* o = find_profile_object(profile, index, sub);
  if (o == nullptr) return {MappingCheck::kNotInProfile};
  if (static_cast<int>(o->size) * 8 != bits) return {MappingCheck::kSizeDiffers, o};
  if (tpdo && !readable(o->access)) return {MappingCheck::kNotReadable, o};
  if (!tpdo && !writable(o->access)) return {MappingCheck::kNotWritable, o};
  return {MappingCheck::kOk, o};
}

const char* mapping_check_text(MappingCheck c) {
  switch (c) {
    case MappingCheck::kOk:
      return "served";
    case MappingCheck::kUnchecked:
      return "manufacturer-specific: checked against the device at boot";
    case MappingCheck::kCommunication:
      return "a communication object (0x1000-0x1FFF) is not mapped into a PDO";
    case MappingCheck::kNotInProfile:
      return "no such object in the node's device profile";
    case MappingCheck::kSizeDiffers:
      return "the object's size differs";
    case MappingCheck::kNotReadable:
      return "the object is write-only: a TPDO cannot send it";
    case MappingCheck::kNotWritable:
      return "the object is read-only: an RPDO cannot write it";
  }
  return "?";
}

}  // namespace planter::canopen
