#include "apps/planter-can/board_file_edit.h"

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "config/board_config.h"
#include "config/config_error.h"
#include "config/durable_file.h"
#include "config/input_file.h"

namespace planter::cantool {
namespace {

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  const auto b = s.find_last_not_of(" \t\r");
  return s.substr(a, b - a + 1);
}

// "[nodes.force_sensor]  # comment" -> "nodes.force_sensor"; "" when not a header.
std::string header_name(const std::string& line) {
  const std::string t = trim(line);
  if (t.size() < 3 || t[0] != '[' || t[1] == '[') return "";
  const auto close = t.find(']');
  if (close == std::string::npos) return "";
  return trim(t.substr(1, close - 1));
}

}  // namespace

void edit_board_text(std::string& text, const std::vector<BoardEdit>& edits) {
  std::vector<std::string> lines;
  {
    std::istringstream in(text);
    std::string l;
    while (std::getline(in, l)) lines.push_back(l);
  }
  for (const auto& e : edits) {
    std::size_t header = lines.size();
    for (std::size_t i = 0; i < lines.size(); ++i) {
      if (header_name(lines[i]) == e.table) header = i;
    }
    if (header == lines.size()) {
      if (!lines.empty() && !trim(lines.back()).empty()) lines.emplace_back();
      lines.push_back("[" + e.table + "]");
      header = lines.size() - 1;
    }
    std::size_t end = header + 1;
    while (end < lines.size() && header_name(lines[end]).empty()) ++end;
    bool replaced = false;
    std::size_t last_key = header;
    for (std::size_t i = header + 1; i < end; ++i) {
      const std::string t = trim(lines[i]);
      if (t.empty() || t[0] == '#') continue;
      last_key = i;
      const auto eq = t.find('=');
      if (eq == std::string::npos || trim(t.substr(0, eq)) != e.key) continue;
      // Keep the comment after the value (values here are numbers: no '#' inside them).
      const auto hash = lines[i].find('#', lines[i].find('='));
      std::string comment;
      if (hash != std::string::npos) comment = "  " + lines[i].substr(hash);
      const std::string indent = lines[i].substr(0, lines[i].find_first_not_of(" \t"));
      lines[i] = indent + e.key + " = " + e.value + comment;
      replaced = true;
      break;
    }
    if (!replaced) {
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(last_key + 1),
                   e.key + " = " + e.value);
    }
  }
  text.clear();
  for (const auto& l : lines) text += l + "\n";
}

bool write_board_edits(const std::string& board_path, const std::vector<BoardEdit>& edits,
                       std::string& error, std::string* backup_written, std::string* written) {
  // The unit's calibration file, or the board itself when it holds its machine (no split).
  std::string link_path = board_path;
  bool calibration = false;
  try {
    const config::BoardConfig board = config::load_board(board_path);
    if (!board.machine_file.empty() && board.calibration_file.empty()) {
      error = board_path +
              ": names no calibration file; add calibration = \"calibration.toml\" to [board] "
              "and create it beside the board file";
      return false;
    }
    if (!board.calibration_file.empty()) {
      link_path = board.calibration_file;
      calibration = true;
    }
  } catch (const config::ConfigError& e) {
    error = e.what();
    return false;
  }
  // Edit the file a symlink names, so /etc/planter/board.toml -> boards/x/board.toml stays a link.
  std::error_code ec;
  const std::string path = std::filesystem::canonical(link_path, ec).string();
  if (ec) {
    error = link_path + ": cannot be resolved: " + ec.message();
    return false;
  }
  std::string original;
  try {
    original = config::read_input_file(path);
  } catch (const config::ConfigError& e) {
    error = e.what();
    return false;
  }
  std::string text = original;
  edit_board_text(text, edits);
  std::string backup = path + ".bak";
  for (int n = 2; std::filesystem::exists(backup, ec) || std::filesystem::is_symlink(backup, ec);
       ++n) {
    backup = path + ".bak." + std::to_string(n);
  }
  // A temporary of its own beside the board file: two runs never share one.
  const std::string tmp = config::write_temporary_beside(path, text);
  if (tmp.empty()) {
    error = path + ": cannot be written beside (" + std::strerror(errno) + ")";
    return false;
  }
  try {
    // The board must still load with the edited file.
    (void)(calibration ? config::load_board(board_path, tmp) : config::load_board(tmp));
  } catch (const config::ConfigError& e) {
    error = std::string("the board would not load with the edit: ") + e.what();
    ::unlink(tmp.c_str());
    return false;
  }
  if (!config::write_file_synced(backup, original)) {
    error = backup + ": cannot be written";
    ::unlink(tmp.c_str());
    return false;
  }
  if (!config::replace_file(tmp, path)) {
    error = path + ": cannot be replaced";
    ::unlink(tmp.c_str());
    return false;
  }
  if (backup_written != nullptr) *backup_written = backup;
  if (written != nullptr) *written = path;
  return true;
}

}  // namespace planter::cantool
