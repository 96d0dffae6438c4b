#pragma once
// How the ground fusion is using the GNSS receiver now (firmware/sensing/ground_fusion.h),
// carried in the controller's report so the console and logs can say it in words.
#include <cstdint>

namespace planter {

enum class GnssUse : std::uint8_t {
  kNone,          // no receiver on the board
  kUsing,         // fixes used
  kNoFix,         // no fix yet, or the receiver says none
  kPoorFix,       // satellites, HDOP or the speed error past the limits
  kStale,         // no new fix for fix_timeout_s (the receiver or gpsd stopped)
  kRefused,       // the speed jumped (the gate) or was implausible
  kDisconnected,  // gpsd or the receiver's link is down
};

// The operator's words for a GnssUse.
const char* gnss_use_name(GnssUse use);

}  // namespace planter
