// Fuzz target: the other files a user hands the tools: a scenario (planter-sim), a planter-fit
// model.toml (--model, planter-sim replay), DEM parameters (planter-dem), and a run plan's
// plan.json (planter-sim plan-run) with each run's settings and disturbances applied. Each load
// either succeeds or throws ConfigError naming the file (a plan: std::runtime_error); never
// anything else. The first byte picks the loader, so one corpus serves all four.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "analysis/model_file.h"
#include "config/config_error.h"
#include "dem/dem_params.h"
#include "sim/runner/run_plan.h"
#include "sim/runner/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  // A scenario names its board and models relative to itself ("../boards/..."), as in the
  // repository: the file is written beside links to the repository's boards and models.
  // Removed when the fuzzer exits (remove_all removes the links, not what they point to).
  struct Scratch {
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("planter-fuzz-config-" + std::to_string(::getpid()));
    Scratch() {
      std::filesystem::create_directories(dir / "scenarios");
      std::error_code ec;
      std::filesystem::create_directory_symlink(PLANTER_SOURCE_DIR "/boards", dir / "boards", ec);
      std::filesystem::create_directory_symlink(PLANTER_SOURCE_DIR "/models", dir / "models", ec);
    }
    ~Scratch() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  };
  static const Scratch scratch;
  static const std::string dir = scratch.dir.string();
  static const std::string path = dir + "/scenarios/fuzz.toml";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (f == nullptr) return 0;
  std::fwrite(data + 1, 1, size - 1, f);
  std::fclose(f);
  if (data[0] % 4 == 3) {
    static const planter::sim::Scenario base =
        planter::sim::load_scenario(PLANTER_SOURCE_DIR "/scenarios/zhangqiu-field.toml");
    try {
      for (const planter::sim::PlannedRun& run : planter::sim::read_plan(path).runs)
        (void)planter::sim::planned_scenario(base, run);
    } catch (const std::runtime_error&) {
    }
    return 0;
  }
  try {
    switch (data[0] % 4) {
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
