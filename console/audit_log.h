#pragma once
// The console's audit log: one line per login and per command, accepted or refused, appended
// with one write and an fdatasync (they are rare and rate-limited): the UTC time, the client's
// address, the session (a short name, never the token), what was asked, the value, the result.
// A log that cannot be written is said once on stderr, the line it cut taken back, and from
// then the console refuses every command but stop: a command that would leave no trace is not
// given, and stopping the machine is never refused for want of a log. The file must be a
// regular file (a FIFO or a device is refused at the start, with its name).
#include <mutex>
#include <string>

namespace planter::console {

class AuditLog {
 public:
  // Opens (creating, mode 0640) for appending; throws std::runtime_error naming the file.
  explicit AuditLog(const std::string& path);
  ~AuditLog();
  AuditLog(const AuditLog&) = delete;
  AuditLog& operator=(const AuditLog&) = delete;

  // False when the line did not reach the disk (and from then on).
  bool append(const std::string& address, const std::string& session, const std::string& what,
              const std::string& value, const std::string& result);
  [[nodiscard]] bool ok();
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  std::mutex mutex_;
  bool ok_ = true;
};

}  // namespace planter::console
