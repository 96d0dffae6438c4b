#pragma once
// Files that must survive a power cut: whole writes, fsync, and atomic replacement (write a
// temporary, fsync it, rename it over the old one, fsync the directory).
#include <cstddef>
#include <string>

namespace planter::config {

// Writes all of `size` bytes to an open descriptor (retrying short writes and EINTR).
bool write_all(int fd, const char* data, std::size_t size);
// Creates or truncates `path`, writes `data` and fsyncs it.
bool write_file_synced(const std::string& path, const std::string& data);
// Renames `from` over `to` and fsyncs the directory so the rename itself is durable.
bool replace_file(const std::string& from, const std::string& to);
// Why `path` may not be replaced by an output ("" when it may): it replaces only a regular
// file or makes a new one; a device, FIFO, socket or directory is refused, and so is a
// symbolic link (outputs do not follow links: the link would become a plain file).
std::string output_target_refusal(const std::string& path);
// Writes `data` to a temporary of its own beside `path` (PATH.XXXXXX, made exclusively),
// fsyncs it and renames it over `path`: a reader sees the old file or the new one, never half of
// one. The temporary is removed on failure; `why` (if given) gets the reason.
bool write_file_atomic(const std::string& path, const std::string& data,
                       std::string* why = nullptr);
// Writes `data` to a new temporary beside `path` (PATH.XXXXXX, made exclusively, fsynced) and
// returns its name, or "" (errno set) when it cannot.
std::string write_temporary_beside(const std::string& path, const std::string& data);
// Why a new log may not be started at `path` ("" when it may): a log is never opened for
// truncation, so a path that exists is refused, whatever it is (issue 28, item 11).
std::string new_log_refusal(const std::string& path);
// The same for a tool's output file: throws std::runtime_error "<path>: <why>".
void write_output_file(const std::string& path, const std::string& data);

}  // namespace planter::config
