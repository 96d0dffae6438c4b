#pragma once
// Names, types and units of the objects this machine's nodes use (CiA 301, 402, 404), so
// reads, PDO values and the monitor speak in the technician's words.
#include <cstdint>
#include <string_view>

namespace planter::cantool {

struct ObjectInfo {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;  // kAnySub: the name holds for every sub-index
  std::string_view name;
  std::string_view type = "u32";  // CiA 309-3 type name
  std::string_view unit;          // "" when it has none or it depends on the node
};
constexpr std::uint8_t kAnySub = 0xFF;

// nullptr when the object is not known.
const ObjectInfo* find_object(std::uint16_t index, std::uint8_t sub);
// "statusword" or "0x2001:03" when unknown; written into `buf`.
std::string_view object_label(std::uint16_t index, std::uint8_t sub, char* buf, std::size_t size);

// Meaning of an EMCY error code (CiA 301 / 402 classes); static strings.
const char* emcy_code_text(std::uint16_t code);
// NMT state of a heartbeat byte ("operational"); 0xFF (none heard yet) is "-".
const char* nmt_state_name(std::uint8_t state);
// Device profile name of a 0x1000 value ("CiA 402 drive").
const char* device_profile_text(std::uint32_t device_type);

}  // namespace planter::cantool
