#include "config/commissioning.h"

#include <fcntl.h>
#include <unistd.h>

#include <cinttypes>
#include <cstdio>
#include <fstream>
#include <iterator>

namespace planter::config {

std::uint64_t board_fingerprint(const std::string& board_path) {
  std::ifstream in(board_path, std::ios::binary);
  if (!in) return 0;
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (std::istreambuf_iterator<char> it(in), end; it != end; ++it) {
    h ^= static_cast<unsigned char>(*it);
    h *= 0x100000001b3ull;
  }
  return h;
}

bool write_commissioning_stamp(const std::string& stamp_path, const std::string& board_path,
                               const std::string& board_name, std::int64_t passed_at_unix_s,
                               std::string& error) {
  char text[512];
  const int n = std::snprintf(
      text, sizeof text,
      "# planter-can check: every item passed\n"
      "board: %s\nboard_file: %s\nboard_fingerprint: %016" PRIx64 "\npassed_at: %" PRId64 "\n",
      board_name.c_str(), board_path.c_str(), board_fingerprint(board_path), passed_at_unix_s);
  const std::string tmp = stamp_path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    error = stamp_path + ": cannot be written";
    return false;
  }
  const bool ok = n > 0 && ::write(fd, text, static_cast<std::size_t>(n)) == n && ::fsync(fd) == 0;
  ::close(fd);
  if (!ok || ::rename(tmp.c_str(), stamp_path.c_str()) != 0) {
    ::unlink(tmp.c_str());
    error = stamp_path + ": cannot be written";
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
    why = board_path + " changed since it was commissioned (" + stamp_path +
          "): run planter-can check again";
    return false;
  }
  why = stamp_path + " is not a commissioning stamp";
  return false;
}

}  // namespace planter::config
