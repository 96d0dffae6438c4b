#pragma once
// Opening a file a user named as input. Every tool reads its inputs through here, so a FIFO,
// a directory or a device is refused with one message instead of blocking in open() or being
// misread, and a UTF-8 byte-order mark (files saved on Windows) is skipped.
#include <cstddef>
#include <string>
#include <string_view>

namespace planter::config {

// Throws ConfigError(path, 0, "", reason) unless `path` names a readable regular file:
// "no such file", "is a directory, not a file", "is a FIFO, not a regular file", ...
void require_regular_file(const std::string& path);

// The whole file (checked as above), without a leading UTF-8 byte-order mark. A file larger
// than max_bytes is refused: these are configuration and command files, not recordings.
std::string read_input_file(const std::string& path, std::size_t max_bytes = 64u << 20);

// Removes a leading UTF-8 byte-order mark from the first line of a streamed file.
void strip_utf8_bom(std::string& first_line);
[[nodiscard]] bool starts_with_utf8_bom(std::string_view text);

// A user's text cut for a message: at most max_chars, control characters shown as '?', and
// "... (N bytes)" when cut, so a 1 MB cell does not make a 1 MB message.
std::string excerpt(std::string_view text, std::size_t max_chars = 40);

}  // namespace planter::config
