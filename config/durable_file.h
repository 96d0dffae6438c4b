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
// Writes `data` to `path` + ".tmp", fsyncs it and renames it over `path`: a reader sees the
// old file or the new one, never half of one. The temporary is removed on failure.
bool write_file_atomic(const std::string& path, const std::string& data);
// The same for a tool's output file: throws std::runtime_error "<path>: cannot be written".
void write_output_file(const std::string& path, const std::string& data);

}  // namespace planter::config
