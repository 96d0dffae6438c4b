#pragma once
// CANopen predefined connection set (CiA 301) and the command bytes this project uses.
#include <cstdint>

namespace planter::canopen {

constexpr std::uint16_t kNmtCobId = 0x000;
constexpr std::uint16_t kSyncCobId = 0x080;
constexpr std::uint16_t kEmcyBase = 0x080;
constexpr std::uint16_t kTpdoBase[4] = {0x180, 0x280, 0x380, 0x480};
constexpr std::uint16_t kRpdoBase[4] = {0x200, 0x300, 0x400, 0x500};
constexpr std::uint16_t kSdoResponseBase = 0x580;
constexpr std::uint16_t kSdoRequestBase = 0x600;
constexpr std::uint16_t kHeartbeatBase = 0x700;

enum class NmtCommand : std::uint8_t {
  kStart = 0x01,
  kStop = 0x02,
  kPreOperational = 0x80,
  kResetNode = 0x81,
  kResetCommunication = 0x82,
};

// State byte in heartbeat frames.
enum class NmtState : std::uint8_t {
  kBootUp = 0x00,
  kStopped = 0x04,
  kOperational = 0x05,
  kPreOperational = 0x7F,
  kUnknown = 0xFF,
};

// SDO abort codes used here (CiA 301 table 22).
namespace abort_code {
constexpr std::uint32_t kToggleBit = 0x05030000;
constexpr std::uint32_t kTimeout = 0x05040000;
constexpr std::uint32_t kBadCommand = 0x05040001;
constexpr std::uint32_t kWriteOnly = 0x06010001;
constexpr std::uint32_t kReadOnly = 0x06010002;
constexpr std::uint32_t kUnsupportedAccess = 0x06010000;
constexpr std::uint32_t kNoObject = 0x06020000;
constexpr std::uint32_t kCannotMap = 0x06040041;
constexpr std::uint32_t kMapLength = 0x06040042;
constexpr std::uint32_t kLength = 0x06070010;
constexpr std::uint32_t kNoSubIndex = 0x06090011;
constexpr std::uint32_t kValueRange = 0x06090030;
constexpr std::uint32_t kGeneral = 0x08000000;
constexpr std::uint32_t kCannotStore = 0x08000020;
constexpr std::uint32_t kDeviceState = 0x08000022;
}  // namespace abort_code

// Human meaning of an abort code; static strings only.
const char* abort_code_text(std::uint32_t code);

}  // namespace planter::canopen
