// Fuzz target: a board file with its machine file and calibration. Loading either succeeds or
// throws ConfigError with a message naming the file (one of the three) and key; never anything
// else.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>
#include <string_view>

#include "config/board_config.h"
#include "config/config_error.h"

namespace {
// The input is the board file, then optionally the machine file and the calibration, each after
// a line "#@machine" or "#@calibration": a board names its machine (machines/<name>.toml), so
// the machine's sections are fuzzed through their own file, as they are read.
void write(const std::string& path, std::string_view text) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return;
  if (!text.empty())
    std::fwrite(text.data(), 1, text.size(), f);  // an empty view's data() may be null
  std::fclose(f);
}
std::string_view cut(std::string_view& rest, std::string_view marker) {
  const auto at = rest.find(marker);
  if (at == std::string_view::npos) {
    std::string_view all = rest;
    rest = {};
    return all;
  }
  std::string_view head = rest.substr(0, at);
  rest.remove_prefix(at + marker.size());
  return head;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // In a folder of its own: a calibration and a machine the input names resolve beside it, to
  // nothing else.
  // Removed when the fuzzer exits.
  struct Scratch {
    std::string dir = "/tmp/planter-fuzz-board-" + std::to_string(::getpid());
    Scratch() { std::filesystem::create_directories(dir + "/machines"); }
    ~Scratch() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  };
  static const Scratch scratch;
  const std::string& dir = scratch.dir;
  const std::string path = dir + "/board.toml";
  std::string_view rest(reinterpret_cast<const char*>(data), size);
  const std::string_view board = cut(rest, "\n#@machine\n");
  const std::string_view machine = cut(rest, "\n#@calibration\n");
  write(path, board);
  write(dir + "/machines/scallion-transplanter.toml", machine);
  write(dir + "/calibration.toml", rest);
  try {
    (void)planter::config::load_board(path);
  } catch (const planter::config::ConfigError& e) {
    if (std::string(e.what()).find(dir) == std::string::npos) __builtin_trap();
  }
  return 0;
}
