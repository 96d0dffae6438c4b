#pragma once
// Writes calibration results back into a board file: only the named keys change, comments
// and layout stay; the old file is kept as FILE.bak; the new one replaces it atomically
// (write a temporary, fsync, rename) and must load as a valid board before it is kept.
#include <string>
#include <vector>

namespace planter::cantool {

struct BoardEdit {
  std::string table;  // "encoder", "nodes.force_sensor", "control"
  std::string key;
  std::string value;  // TOML text, e.g. "0.15464"
};

// Applies the edits to the file's text; a key missing from its table is added at its end.
// False with `error` set when a table is missing.
bool edit_board_text(std::string& text, const std::vector<BoardEdit>& edits, std::string& error);
// The whole transaction; false with `error` set, the original file untouched. A symlink is
// followed: the file it names is edited and the link stays. The old text is kept as FILE.bak,
// or FILE.bak.2, .3, ... when earlier backups exist (none is overwritten); `backup` names it.
bool write_board_edits(const std::string& path, const std::vector<BoardEdit>& edits,
                       std::string& error, std::string* backup = nullptr);

}  // namespace planter::cantool
