#pragma once
// An object's access as CiA 301 defines it: what the profile table (profile_objects.h) states
// for each process object and what a device's dictionary (sim/devices/object_dictionary.h)
// enforces. Declared here, below both, so the loader can check mappings without the device.
#include <cstdint>

namespace planter::canopen {

enum class Access : std::uint8_t { kReadOnly, kWriteOnly, kReadWrite, kConst };

}  // namespace planter::canopen
