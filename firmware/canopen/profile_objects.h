#pragma once
// The process objects of the device profiles the machine's nodes follow, as the standards
// define them: CiA 402 (drives and motion control) and CiA 404 (measuring devices), each with
// its size and access. The simulated nodes build their dictionaries from this table, and the
// loader checks every PDO mapping of a machine file against it, so a mapping the device cannot
// serve (an object it lacks, a size that differs, a read-only object in an RPDO) is refused
// before a run instead of failing the boot (issue 28, item 12).
#include <cstdint>
#include <span>

#include "firmware/canopen/access.h"

namespace planter::canopen {

struct ProfileObject {
  std::uint16_t index;
  std::uint8_t sub;
  std::uint8_t size;  // bytes
  Access access;
};

// 402 or 404; empty for any other profile.
std::span<const ProfileObject> profile_objects(std::uint16_t profile);
const ProfileObject* find_profile_object(std::uint16_t profile, std::uint16_t index,
                                         std::uint8_t sub);

enum class MappingCheck : std::uint8_t {
  kOk,
  kUnchecked,      // manufacturer-specific (0x2000-0x5FFF) or a dummy entry: the boot checks it
  kCommunication,  // 0x1000-0x1FFF: communication objects are not mapped here
  kNotInProfile,   // in the profile's area, but the profile has no such object
  kSizeDiffers,    // the mapping's bits are not the object's size
  kNotReadable,    // in a TPDO: the device cannot send it
  kNotWritable,    // in an RPDO: the device cannot take it
};
struct MappingVerdict {
  MappingCheck check = MappingCheck::kOk;
  const ProfileObject* object = nullptr;  // the profile's object, where there is one
  [[nodiscard]] bool served() const {
    return check == MappingCheck::kOk || check == MappingCheck::kUnchecked;
  }
};
// Whether a node of this profile can serve the entry, sent (tpdo) or received.
MappingVerdict check_mapping(std::uint16_t profile, std::uint16_t index, std::uint8_t sub,
                             std::uint8_t bits, bool tpdo);
const char* mapping_check_text(MappingCheck c);

}  // namespace planter::canopen
