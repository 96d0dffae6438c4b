#pragma once
// A tool run's output files, which a reader sees as the old set or the new set, never a mix.
//
// The files are written into a staging directory beside the output directory
// (`DIR.partial-<pid>`); commit() writes the manifest `run.json` last (the tool, and each file
// with its size), fsyncs, and swaps the staging directory into place with one atomic rename
// (RENAME_EXCHANGE when DIR exists), then removes the old set. A run killed before commit()
// leaves DIR untouched; its staging directory is removed by the next run into DIR.
//
// DIR is replaced only when it is empty or holds an earlier run of the same tool and nothing
// else (its manifest lists every file); anything else is refused unless `force` is given. DIR
// as a symbolic link is refused even with `force`.
#include <cstdint>
#include <string>
#include <vector>

namespace planter::config {

class OutputSet {
 public:
  // Throws std::runtime_error naming DIR when it holds something else and force is false, or
  // when the staging directory cannot be made.
  OutputSet(std::string dir, std::string tool, bool force);
  ~OutputSet();  // removes the staging directory if commit() was not reached
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  // Where to write `name` now (inside the staging directory); the file is part of the set.
  std::string path(const std::string& name);
  // `DIR/name`: how messages name the file, wherever it is written now.
  [[nodiscard]] std::string shown(const std::string& name) const { return dir_ + "/" + name; }
  // Writes `data` to `name` with every write, flush and close checked; throws naming the file.
  void write(const std::string& name, const std::string& data);
  // Makes the set visible as DIR. Throws naming the file that could not be written or synced.
  void commit();

  [[nodiscard]] const std::string& dir() const { return dir_; }

 private:
  std::string dir_, tool_, staging_;
  std::vector<std::string> names_;
  bool committed_ = false;
};

// Why `dir` may not be replaced by a run of `tool` ("" when it may): it is missing, empty, or
// holds an earlier run of the same tool and nothing else (every file in its run.json), or
// `force` is given. A symbolic link or a file that is no directory is refused even with force.
[[nodiscard]] std::string output_dir_refusal(const std::string& dir, const std::string& tool,
                                             bool force);

// Whether `dir` holds a whole run of `tool`: its manifest names the tool, and every file it lists
// is there as a regular file of the size it records. A run the disk or a kill tore is not whole
// and is run again (plan runs and the DEM's kept runs alike).
[[nodiscard]] bool output_set_whole(const std::string& dir, const std::string& tool);

// Makes `dir` and its parents as needed; throws std::runtime_error "<dir>: cannot be created:
// <why>" (never the library's own text) when it cannot.
void make_directories(const std::string& dir);

// The manifest's file name.
inline constexpr const char* kRunManifest = "run.json";

}  // namespace planter::config
