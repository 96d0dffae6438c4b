#include "firmware/canopen/cob_id.h"

namespace planter::canopen {

const char* abort_code_text(std::uint32_t code) {
  switch (code) {
    case abort_code::kToggleBit:
      return "toggle bit not alternated";
    case abort_code::kTimeout:
      return "SDO protocol timed out";
    case abort_code::kBadCommand:
      return "client/server command specifier not valid or unknown";
    case 0x05040005:
      return "out of memory";
    case 0x06010000:
      return "unsupported access to an object";
    case abort_code::kWriteOnly:
      return "attempt to read a write-only object";
    case abort_code::kReadOnly:
      return "attempt to write a read-only object";
    case abort_code::kNoObject:
      return "object does not exist in the object dictionary";
    case 0x06040041:
      return "object cannot be mapped to the PDO";
    case 0x06040042:
      return "number and length of objects to be mapped would exceed PDO length";
    case 0x06060000:
      return "access failed due to a hardware error";
    case abort_code::kLength:
      return "data type does not match, length of service parameter does not match";
    case 0x06070012:
      return "data type does not match, length of service parameter too high";
    case 0x06070013:
      return "data type does not match, length of service parameter too low";
    case abort_code::kNoSubIndex:
      return "sub-index does not exist";
    case abort_code::kValueRange:
      return "invalid value for parameter";
    case 0x06090031:
      return "value of parameter written too high";
    case 0x06090032:
      return "value of parameter written too low";
    case abort_code::kGeneral:
      return "general error";
    case 0x08000020:
      return "data cannot be transferred or stored to the application";
    case 0x08000021:
      return "data cannot be transferred because of local control";
    case abort_code::kDeviceState:
      return "data cannot be transferred because of the present device state";
    default:
      return "unknown abort code";
  }
}

}  // namespace planter::canopen
