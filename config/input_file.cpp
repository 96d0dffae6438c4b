#include "config/input_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "config/config_error.h"

namespace planter::config {

namespace {

constexpr std::string_view kBom = "\xEF\xBB\xBF";

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO, not a regular file";
  if (S_ISSOCK(mode)) return "is a socket, not a regular file";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a regular file";
  return "is not a regular file";
}

[[noreturn]] void refuse(const std::string& path, const std::string& why) {
  throw ConfigError(path, 0, "", why);
}

std::string open_error(int err) {
  if (err == ENOENT) return "no such file";
  if (err == EACCES) return "permission denied";
  return std::string("cannot be opened: ") + std::strerror(err);
}

// Opens without blocking (a FIFO with no writer would block a plain open) and checks the kind
// on the opened descriptor, so the file checked is the file read.
int open_regular(const std::string& path, struct stat& st) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) refuse(path, open_error(errno));
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    const mode_t mode = st.st_mode;
    ::close(fd);
    refuse(path, kind_of(mode));
  }
  return fd;
}

}  // namespace

void require_regular_file(const std::string& path) {
  struct stat st {};
  ::close(open_regular(path, st));
}

std::string read_input_file(const std::string& path, std::size_t max_bytes) {
  struct stat st {};
  const int fd = open_regular(path, st);
  if (static_cast<std::size_t>(st.st_size) > max_bytes) {
    ::close(fd);
    refuse(path, "is " + std::to_string(st.st_size) + " bytes; at most " +
                     std::to_string(max_bytes) + " are read");
  }
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      refuse(path, std::string("cannot be read: ") + std::strerror(err));
    }
    if (n == 0) break;
    text.append(buffer, static_cast<std::size_t>(n));
    if (text.size() > max_bytes) {
      ::close(fd);
      refuse(path, "is larger than the " + std::to_string(max_bytes) + " bytes read");
    }
  }
  ::close(fd);
  if (starts_with_utf8_bom(text)) text.erase(0, kBom.size());
  return text;
}

bool starts_with_utf8_bom(std::string_view text) { return text.substr(0, kBom.size()) == kBom; }

void strip_utf8_bom(std::string& first_line) {
  if (starts_with_utf8_bom(first_line)) first_line.erase(0, kBom.size());
}

std::string excerpt(std::string_view text, std::size_t max_chars) {
  std::string out;
  for (std::size_t i = 0; i < text.size() && i < max_chars; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    out += (c < 0x20 || c == 0x7F) ? '?' : static_cast<char>(c);
  }
  if (text.size() > max_chars) out += "... (" + std::to_string(text.size()) + " bytes)";
  return out;
}

}  // namespace planter::config
