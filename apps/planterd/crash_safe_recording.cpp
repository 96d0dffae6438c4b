#include "apps/planterd/crash_safe_recording.h"

#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <stdexcept>

#include "config/durable_file.h"
#include "config/recording_format.h"

namespace planter::daemon {
namespace {

std::runtime_error io_error(const std::string& path, const std::string& what) {
  return std::runtime_error(path + ": " + what + ": " + std::strerror(errno));
}

}  // namespace

std::uint64_t repair_torn_tail(const std::string& path) {
  const int fd = open(path.c_str(), O_RDWR | O_CLOEXEC);
  if (fd < 0) throw io_error(path, "cannot open to repair");
  struct stat st {};
  fstat(fd, &st);
  const off_t size = st.st_size;
  off_t keep = size;
  char buf[4096];
  // Scan back from the end to the last newline.
  while (keep > 0) {
    const off_t start =
        keep > static_cast<off_t>(sizeof buf) ? keep - static_cast<off_t>(sizeof buf) : 0;
    const ssize_t n = pread(fd, buf, static_cast<std::size_t>(keep - start), start);
    if (n <= 0) break;
    ssize_t i = n - 1;
    while (i >= 0 && buf[i] != '\n') --i;
    if (i >= 0) {
      keep = start + i + 1;
      break;
    }
    keep = start;
  }
  std::uint64_t removed = static_cast<std::uint64_t>(size - keep);
  if (removed > 0 && (ftruncate(fd, keep) != 0 || fsync(fd) != 0)) {
    close(fd);
    throw io_error(path, "cannot cut the torn tail");
  }
  close(fd);
  return removed;
}

CrashSafeRecording::CrashSafeRecording(const std::string& path,
                                       const std::vector<std::string>& metadata)
    : path_(path) {
  if (access(path.c_str(), F_OK) == 0) {
    repair_torn_tail(path);
    for (int n = 1;; ++n) {
      const std::string aside = path + "." + std::to_string(n);
      if (access(aside.c_str(), F_OK) != 0) {
        if (rename(path.c_str(), aside.c_str()) != 0) throw io_error(path, "cannot move aside");
        moved_aside_ = aside;
        break;
      }
    }
  }
  fd_ = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_APPEND | O_CLOEXEC, 0644);
  if (fd_ < 0) throw io_error(path, "cannot create");
  std::string head;
  for (const std::string& m : metadata) head += "# " + m + "\n";
  head += config::controller_columns();
  head += "\n";
  if (!config::write_all(fd_, head.data(), head.size()) || fdatasync(fd_) != 0)
    throw io_error(path, "cannot write the header");
  block_.reserve(1 << 16);
}

CrashSafeRecording::~CrashSafeRecording() {
  if (fd_ >= 0) {
    flush();
    close(fd_);
  }
}

bool CrashSafeRecording::add(double t_s, const Telemetry& row) {
  char line[2048];
  const int n = config::format_controller_columns(line, sizeof line - 1, t_s, row);
  if (n <= 0 || static_cast<std::size_t>(n) >= sizeof line - 1) {
    ++rows_unformatted_;
    return false;
  }
  line[n] = '\n';
  block_.append(line, static_cast<std::size_t>(n) + 1);
  ++rows_pending_;
  return true;
}

bool CrashSafeRecording::flush() {
  if (block_.empty()) return true;
  // One write of whole rows: a crash leaves either the block or (rarely, mid-copy) a tail
  // that the next start cuts back to the last complete row.
  if (!config::write_all(fd_, block_.data(), block_.size()) || fdatasync(fd_) != 0) return false;
  block_.clear();
  rows_written_ += rows_pending_;
  rows_pending_ = 0;
  ++blocks_written_;
  return true;
}

}  // namespace planter::daemon
