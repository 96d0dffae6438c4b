#include "config/commissioning.h"

#include <unistd.h>

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <vector>

#include "config/board_config.h"
#include "config/config_error.h"
#include "config/durable_file.h"

namespace planter::config {

std::uint64_t board_fingerprint(const std::string& board_path) {
  // The board, and the machine and calibration it names: a change to any of them is a change
  // to what was commissioned. A board that does not load is fingerprinted alone (and will not
  // start planterd anyway).
  std::vector<std::string> files{board_path};
  try {
    files = source_files(load_board(board_path));
  } catch (const ConfigError&) {
  }
  std::uint64_t h = 0xcbf29ce484222325ull;
  auto mix = [&h](unsigned char c) {
    h ^= c;
    h *= 0x100000001b3ull;
  };
  for (const std::string& f : files) {
    std::ifstream in(f, std::ios::binary);
    if (!in) return 0;
    for (std::istreambuf_iterator<char> it(in), end; it != end; ++it)
      mix(static_cast<unsigned char>(*it));
    mix(0);  // a file boundary: moving a line from one file to the next changes the print
  }
  return h;
}

bool write_commissioning_stamp(const std::string& stamp_path, const std::string& board_path,
                               const std::string& board_name, std::int64_t passed_at_unix_s,
                               std::string& error) {
  char fingerprint[32];
  std::snprintf(fingerprint, sizeof fingerprint, "%016" PRIx64, board_fingerprint(board_path));
  // Built as a string: board names and paths have no length limit here.
  const std::string text = "# planter-can check: every item passed\nboard: " + board_name +
                           "\nboard_file: " + board_path + "\nboard_fingerprint: " + fingerprint +
                           "\npassed_at: " + std::to_string(passed_at_unix_s) + "\n";
  if (std::string why; !write_file_atomic(stamp_path, text, &why)) {
    error = stamp_path + ": " + why;
    return false;
  }
  return true;
}

bool commissioned(const std::string& stamp_path, const std::string& board_path, std::string& why) {
  std::ifstream in(stamp_path);
  if (!in) {
    why = "no commissioning stamp " + stamp_path + " (run: planter-can check --mark-commissioned " +
          stamp_path + ")";
    return false;
  }
  std::string line;
  const std::string key = "board_fingerprint: ";
  while (std::getline(in, line)) {
    if (line.rfind(key, 0) != 0) continue;
    char now[32];
    std::snprintf(now, sizeof now, "%016" PRIx64, board_fingerprint(board_path));
    if (line.substr(key.size()) == now) return true;
    why = board_path + " (or the machine or calibration it names) changed since it was " +
          "commissioned (" + stamp_path + "): run planter-can check again";
    return false;
  }
  why = stamp_path + " is not a commissioning stamp";
  return false;
}

}  // namespace planter::config
