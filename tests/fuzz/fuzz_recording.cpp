// Fuzz target: planter-fit's recording reader. Any input gives a Recording or one
// RecordingError; never a crash, a hang or another exception.
#include <cstddef>
#include <cstdint>
#include <string>

#include "analysis/recording.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const planter::analysis::Recording r = planter::analysis::parse_recording(text, "fuzz", 1);
    for (const auto& [name, v] : r.signals)
      if (v.size() != r.t.size()) __builtin_trap();  // every column as long as time
  } catch (const planter::analysis::RecordingError&) {
  }
  return 0;
}
