#pragma once
// Commissioning stamp: `planter-can check --mark-commissioned FILE` writes it when every item
// of the checklist passed; planterd (with --commissioned-stamp FILE) starts the drives only
// while it exists and was written for this very board (a fingerprint of the bytes of the board
// file, its machine file and its calibration), so editing any of them after commissioning asks
// for a new check.
#include <cstdint>
#include <string>

namespace planter::config {

// FNV-1a 64 of the board's files' bytes (change detection, not security); 0 when unreadable.
std::uint64_t board_fingerprint(const std::string& board_path);

// Writes the stamp atomically (temporary, fsync, rename). False with `error` set on failure.
bool write_commissioning_stamp(const std::string& stamp_path, const std::string& board_path,
                               const std::string& board_name, std::int64_t passed_at_unix_s,
                               std::string& error);

// True when the stamp exists and names this board file's current fingerprint; otherwise
// false with `why` saying what is missing.
bool commissioned(const std::string& stamp_path, const std::string& board_path, std::string& why);

}  // namespace planter::config
