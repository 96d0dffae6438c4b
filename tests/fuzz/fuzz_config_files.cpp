// Fuzz target: the other TOML files a user hands the tools: a scenario (planter-sim), a
// planter-fit model.toml (--model, planter-sim replay) and DEM parameters (planter-dem). Each
// load either succeeds or throws ConfigError naming the file; never anything else. The first
// byte picks the loader, so one corpus serves all three.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "analysis/model_file.h"
#include "config/config_error.h"
#include "dem/dem_params.h"
#include "sim/runner/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  // A scenario names its board and models relative to itself ("../boards/..."), as in the
  // repository: the file is written beside links to the repository's boards and models.
  static const std::string dir = [] {
    namespace fs = std::filesystem;
    const fs::path d =
        fs::temp_directory_path() / ("planter-fuzz-config-" + std::to_string(::getpid()));
    fs::create_directories(d / "scenarios");
    std::error_code ec;
    fs::create_directory_symlink(PLANTER_SOURCE_DIR "/boards", d / "boards", ec);
    fs::create_directory_symlink(PLANTER_SOURCE_DIR "/models", d / "models", ec);
    return d.string();
  }();
  static const std::string path = dir + "/scenarios/fuzz.toml";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  try {
    switch (data[0] % 3) {
      case 0:
        (void)planter::sim::load_scenario(path);
        break;
      case 1:
        (void)planter::analysis::load_augmented_model(path);
        break;
      default:
        (void)planter::dem::load_compression_setup(path);
        break;
    }
  } catch (const planter::config::ConfigError& e) {
    if (std::string(e.what()).find(path) == std::string::npos) __builtin_trap();
  }
  return 0;
}
