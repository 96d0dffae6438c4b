#pragma once
// Writes calibration results into the unit's calibration file (the one the board names; a
// board file that holds its machine itself is edited in place): only the named keys change,
// comments and layout stay; the old file is kept as FILE.bak; the new one replaces it
// atomically (write a temporary, fsync, rename) and the board must load with it before it is
// kept.
#include <string>
#include <vector>

namespace planter::cantool {

struct BoardEdit {
  std::string table;  // "encoder", "nodes.force_sensor", "control"
  std::string key;
  std::string value;  // TOML text, e.g. "0.15464"
};

// Applies the edits to the file's text; a key missing from its table is added at its end, a
// missing table at the end of the file.
void edit_board_text(std::string& text, const std::vector<BoardEdit>& edits);
// The whole transaction; false with `error` set, the original file untouched. A symlink is
// followed: the file it names is edited and the link stays. The old text is kept as FILE.bak,
// or FILE.bak.2, .3, ... when earlier backups exist (none is overwritten); `backup` names it.
// `board_path` is the board file; `written` names the file edited.
bool write_board_edits(const std::string& board_path, const std::vector<BoardEdit>& edits,
                       std::string& error, std::string* backup = nullptr,
                       std::string* written = nullptr);

}  // namespace planter::cantool
