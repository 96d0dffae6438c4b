#pragma once
// The augmented model planter-fit writes (model.toml): per channel, the nominal parameters
// and the effects with their values. `planter-sim replay` runs it on a recording's inputs.
#include <string>
#include <vector>

#include "sim/analysis/channel_model.h"

namespace planter::analysis {

struct ModelChannel {
  const ChannelModel* channel = nullptr;
  std::vector<double> nominal;
  std::vector<Effect> effects;
};

// A parameter or effect name as a TOML key (what fit_model_toml writes, what this reads).
std::string model_key(const std::string& name);

// Throws config::ConfigError (file, line, key, allowed values).
std::vector<ModelChannel> load_augmented_model(const std::string& path);

}  // namespace planter::analysis
