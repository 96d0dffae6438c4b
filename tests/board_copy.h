#pragma once
// A scratch copy of one of the project's boards: its board.toml and calibration.toml in a new
// folder, with machines/ linked beside them so the board finds its machine file.
#include <filesystem>
#include <string>

namespace planter::test {

inline std::filesystem::path copy_board(const std::string& board,
                                        const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const fs::path source = fs::path(PLANTER_SOURCE_DIR);
  fs::create_directories(dir);
  for (const char* f : {"board.toml", "calibration.toml"})
    fs::copy_file(source / "boards" / board / f, dir / f, fs::copy_options::overwrite_existing);
  if (!fs::exists(dir / "machines"))
    fs::create_directory_symlink(source / "machines", dir / "machines");
  return dir / "board.toml";
}

}  // namespace planter::test
