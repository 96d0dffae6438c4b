#include "console/audit_log.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <stdexcept>

#include "config/durable_file.h"

namespace planter::console {
namespace {
// Values come from the network: a line stays one line, printable, with no quote. Fields keep
// no space (a space ends them); the result is in words and keeps its spaces.
std::string printable(const std::string& s, std::size_t max_chars, bool spaces) {
  std::string out;
  for (char c : s.substr(0, max_chars)) {
    const auto u = static_cast<unsigned char>(c);
    out.push_back(u >= (spaces ? 0x20 : 0x21) && u < 0x7f && c != '"' ? c : '_');
  }
  return out;
}
std::string field(const std::string& s) {
  const std::string out = printable(s, 80, false);
  return out.empty() ? "-" : out;
}
}  // namespace

namespace {
// A regular file, or a character device (/dev/null, /dev/full); a FIFO would block the console
// on its first line, a socket or a directory takes no lines.
bool may_log_to(const struct stat& st) { return S_ISREG(st.st_mode) || S_ISCHR(st.st_mode); }
}  // namespace

AuditLog::AuditLog(const std::string& path) : path_(path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) == 0 && !may_log_to(st))
    throw std::runtime_error(path + ": the console's audit log must be a regular file");
  // Non-blocking while it is checked: a FIFO put there since would otherwise hold the start.
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NONBLOCK, 0640);
  if (fd_ < 0)
    throw std::runtime_error(path +
                             ": the console's audit log cannot be opened: " + std::strerror(errno));
  if (::fstat(fd_, &st) != 0 || !may_log_to(st)) {
    ::close(fd_);
    fd_ = -1;
    throw std::runtime_error(path + ": the console's audit log must be a regular file");
  }
  ::fcntl(fd_, F_SETFL, O_APPEND);
}

AuditLog::~AuditLog() {
  if (fd_ >= 0) ::close(fd_);
}

bool AuditLog::append(const std::string& address, const std::string& session,
                      const std::string& what, const std::string& value,
                      const std::string& result) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!ok_) return false;
  timespec now{};
  clock_gettime(CLOCK_REALTIME, &now);
  std::tm utc{};
  gmtime_r(&now.tv_sec, &utc);
  char when[40];
  std::strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%S", &utc);
  char ms[24];
  std::snprintf(ms, sizeof ms, ".%03ldZ", now.tv_nsec / 1'000'000);
  const std::string line =
      std::string(when) + ms + " from=" + field(address) + " session=" + field(session) + " " +
      field(what) + " value=" + field(value) + " result=\"" + printable(result, 200, true) + "\"\n";
  const off_t before = ::lseek(fd_, 0, SEEK_END);
  if (!config::write_all(fd_, line.data(), line.size()) || ::fdatasync(fd_) != 0) {
    const int err = errno;
    // No line is left cut: what reached the file of this one is taken back.
    if (before >= 0 && ::ftruncate(fd_, before) == 0) ::fdatasync(fd_);
    std::fprintf(stderr,
                 "console: %s: cannot be written (%s): commands but stop are refused from now\n",
                 path_.c_str(), std::strerror(err));
    ok_ = false;
  }
  return ok_;
}

bool AuditLog::ok() {
  std::lock_guard<std::mutex> lock(mutex_);
  return ok_;
}

}  // namespace planter::console
