#include "config/durable_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace planter::config {

bool write_all(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool write_file_synced(const std::string& path, const std::string& data) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return false;
  const bool ok = write_all(fd, data.data(), data.size()) && ::fsync(fd) == 0;
  return ::close(fd) == 0 && ok;
}

bool replace_file(const std::string& from, const std::string& to) {
  if (std::rename(from.c_str(), to.c_str()) != 0) return false;
  const auto slash = to.find_last_of('/');
  const std::string dir = slash == std::string::npos ? "." : to.substr(0, slash);
  const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
  return true;
}

std::string output_target_refusal(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return "";  // a new file
  if (S_ISLNK(st.st_mode))
    return "is a symbolic link; outputs do not follow links: give the file itself";
  if (S_ISDIR(st.st_mode)) return "is a directory";
  if (!S_ISREG(st.st_mode))
    return "is a device, FIFO or socket, not a file: outputs replace only regular files";
  return "";
}

std::string new_log_refusal(const std::string& path) {
  struct stat st {};
  if (::lstat(path.c_str(), &st) != 0) return "";
  return "exists: a log is never overwritten; give a new name, or move the old log away";
}

bool write_file_atomic(const std::string& path, const std::string& data, std::string* why) {
  const auto say = [&](const std::string& words) {
    if (why != nullptr) *why = words;
    return false;
  };
  if (const std::string refusal = output_target_refusal(path); !refusal.empty())
    return say(refusal);
  const std::string tmp = write_temporary_beside(path, data);
  if (tmp.empty()) return say(std::string("cannot be written: ") + std::strerror(errno));
  if (replace_file(tmp, path)) return true;
  const int err = errno;
  ::unlink(tmp.c_str());
  return say(std::string("cannot be written: ") + std::strerror(err));
}

std::string write_temporary_beside(const std::string& path, const std::string& data) {
  std::string tmp = path + ".XXXXXX";
  const int fd = ::mkostemp(tmp.data(), O_CLOEXEC);
  if (fd < 0) return "";
  ::fchmod(fd, 0644);
  const bool written = write_all(fd, data.data(), data.size()) && ::fsync(fd) == 0;
  const int err = errno;
  if (::close(fd) == 0 && written) return tmp;
  ::unlink(tmp.c_str());
  errno = err;
  return "";
}

void write_output_file(const std::string& path, const std::string& data) {
  std::string why;
  if (!write_file_atomic(path, data, &why)) throw std::runtime_error(path + ": " + why);
}

}  // namespace planter::config
