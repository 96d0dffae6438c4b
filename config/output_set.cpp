#include "config/output_set.h"

#include <fcntl.h>
#include <signal.h>
#include <stdio.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>

#include "config/durable_file.h"

namespace planter::config {

namespace fs = std::filesystem;

namespace {

constexpr long kPidMax = 4194304;  // Linux's PID_MAX_LIMIT

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw std::runtime_error(path + ": " + what);
}

void fsync_path(const std::string& path, int flags) {
  const int fd = ::open(path.c_str(), flags | O_CLOEXEC);
  if (fd < 0) fail(path, std::string("cannot be opened to sync: ") + std::strerror(errno));
  const int rc = ::fsync(fd);
  const int err = errno;
  ::close(fd);
  if (rc != 0) fail(path, std::string("cannot be synced: ") + std::strerror(err));
}

std::string parent_of(const std::string& dir) {
  const fs::path p = fs::path(dir).lexically_normal();
  const fs::path parent = p.has_parent_path() ? p.parent_path() : fs::path(".");
  return parent.empty() ? "." : parent.string();
}

// Staging directories of runs that were killed: `DIR.partial-<pid>` whose process is gone.
void remove_abandoned_staging(const std::string& dir) {
  const fs::path p = fs::path(dir).lexically_normal();
  const std::string prefix = p.filename().string() + ".partial-";
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(parent_of(dir), ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::string pid_text = name.substr(prefix.size());
    // Only a process number this machine can have: anything else is not ours (issue 28, 10).
    long pid = 0;
    const auto [end, err] =
        std::from_chars(pid_text.data(), pid_text.data() + pid_text.size(), pid);
    if (pid_text.empty() || err != std::errc() || end != pid_text.data() + pid_text.size() ||
        pid <= 0 || pid > kPidMax)
      continue;
    if (::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) {
      fs::remove_all(e.path(), ec);
    }
  }
}

// The files an earlier run of `tool` in `dir` lists in its manifest (name -> size; an empty
// object when it lists none), or nothing when `dir` holds no manifest of that tool.
std::optional<nlohmann::json> manifest_files(const std::string& dir, const std::string& tool) {
  std::ifstream in(dir + "/" + kRunManifest);
  if (!in) return std::nullopt;
  const nlohmann::json manifest = nlohmann::json::parse(in, nullptr, false);
  if (!manifest.is_object() || manifest.value("tool", std::string()) != tool) return std::nullopt;
  return manifest.value("files", nlohmann::json::object());
}

}  // namespace

std::string output_dir_refusal(const std::string& dir, const std::string& tool, bool force) {
  std::error_code ec;
  if (fs::is_symlink(dir, ec))
    return "is a symbolic link; outputs do not follow links: give the directory itself";
  if (!fs::exists(dir, ec)) return "";
  if (!fs::is_directory(dir, ec)) return "exists and is not a directory";
  if (force || fs::is_empty(dir, ec)) return "";
  const std::string other = "holds files that are not the output of '" + tool +
                            "' (no run.json of it); choose another --out, or give --force to "
                            "replace the directory";
  const std::optional<nlohmann::json> files = manifest_files(dir, tool);
  if (!files) return other;
  // Every file in it must be one the earlier run wrote: a file someone left there is theirs.
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name != kRunManifest && !(files->is_object() && files->contains(name)))
      return "holds " + name +
             ", which the earlier run did not write; move it, or give --force "
             "to replace the directory";
  }
  return "";
}

void make_directories(const std::string& dir) {
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) fail(dir, "cannot be created: " + ec.message());
}

OutputSet::OutputSet(std::string dir, std::string tool, bool force)
    : dir_(std::move(dir)), tool_(std::move(tool)) {
  while (dir_.size() > 1 && dir_.back() == '/') dir_.pop_back();
  std::error_code ec;
  if (const std::string refusal = output_dir_refusal(dir_, tool_, force); !refusal.empty())
    fail(dir_, refusal);
  make_directories(parent_of(dir_));
  remove_abandoned_staging(dir_);
  staging_ = dir_ + ".partial-" + std::to_string(::getpid());
  fs::remove_all(staging_, ec);
  if (::mkdir(staging_.c_str(), 0755) != 0) {
    fail(staging_, std::string("cannot be created: ") + std::strerror(errno));
  }
}

OutputSet::~OutputSet() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
}

std::string OutputSet::path(const std::string& name) {
  for (const auto& n : names_) {
    if (n == name) return staging_ + "/" + name;
  }
  names_.push_back(name);
  return staging_ + "/" + name;
}

bool output_set_whole(const std::string& dir, const std::string& tool) {
  const std::optional<nlohmann::json> files = manifest_files(dir, tool);
  if (!files || !files->is_object() || files->empty()) return false;
  for (const auto& [name, size] : files->items()) {
    struct stat st {};
    const std::string p = dir + "/" + name;
    if (!size.is_number_unsigned() || ::lstat(p.c_str(), &st) != 0 || !S_ISREG(st.st_mode) ||
        static_cast<std::uint64_t>(st.st_size) != size.get<std::uint64_t>())
      return false;
  }
  return true;
}

void OutputSet::write(const std::string& name, const std::string& data) {
  const std::string p = path(name);
  if (!write_file_synced(p, data)) {
    fail(dir_ + "/" + name, std::string("cannot be written: ") + std::strerror(errno));
  }
}

void OutputSet::commit() {
  nlohmann::json manifest{{"tool", tool_}, {"files", nlohmann::json::object()}};
  for (const std::string& name : names_) {
    const std::string p = staging_ + "/" + name;
    struct stat st {};
    if (::stat(p.c_str(), &st) != 0) fail(dir_ + "/" + name, "was not written");
    fsync_path(p, O_RDONLY);
    manifest["files"][name] = st.st_size;
  }
  write(kRunManifest, manifest.dump(1) + "\n");
  fsync_path(staging_, O_RDONLY | O_DIRECTORY);
  std::error_code ec;
  const bool existed = fs::exists(dir_, ec);
  if (!existed) {
    if (::rename(staging_.c_str(), dir_.c_str()) != 0) {
      fail(dir_, std::string("cannot be created: ") + std::strerror(errno));
    }
  } else if (::renameat2(AT_FDCWD, staging_.c_str(), AT_FDCWD, dir_.c_str(), RENAME_EXCHANGE) !=
             0) {
    // A file system without RENAME_EXCHANGE: move the old set aside first. A reader between
    // the two renames finds no directory, never a mix.
    const std::string old = dir_ + ".old-" + std::to_string(::getpid());
    if (::rename(dir_.c_str(), old.c_str()) != 0 || ::rename(staging_.c_str(), dir_.c_str()) != 0) {
      fail(dir_, std::string("cannot be replaced: ") + std::strerror(errno));
    }
    fs::remove_all(old, ec);
  }
  committed_ = true;
  fs::remove_all(staging_, ec);  // after an exchange: the old set
  fsync_path(parent_of(dir_), O_RDONLY | O_DIRECTORY);
}

}  // namespace planter::config
