#pragma once
// planter-sim replay MODEL RECORDING: runs planter-fit's augmented model (model.toml) on the
// recording's inputs and compares each output with the recording.
#include <string>

namespace planter::sim {

// Writes DIR/replay.csv (t, then measured and simulated per channel) and prints the RMS error
// per channel. Throws config::ConfigError or analysis::RecordingError for bad files.
int run_replay(const std::string& model_path, const std::string& recording_path,
               const std::string& out_dir, bool force);

}  // namespace planter::sim
