// Fuzz target: a board file. Loading either succeeds or throws ConfigError with a message
// naming file and key; never anything else.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "config/board_config.h"
#include "config/config_error.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // In a folder of its own: a calibration the input names resolves beside it, to nothing else.
  static const std::string path = [] {
    const std::string dir = "/tmp/planter-fuzz-board-" + std::to_string(::getpid());
    std::filesystem::create_directories(dir);
    return dir + "/board.toml";
  }();
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return 0;
  std::fwrite(data, 1, size, f);
  std::fclose(f);
  try {
    (void)planter::config::load_board(path);
  } catch (const planter::config::ConfigError& e) {
    if (std::string(e.what()).find(path) == std::string::npos) __builtin_trap();
  }
  return 0;
}
