#pragma once
// The augmented model planter-fit writes (model.toml): per channel, the nominal parameters
// and the effects with their values. `planter-sim replay` runs it on a recording's inputs.
#include <string>
#include <vector>

#include "analysis/channel_model.h"

namespace planter::analysis {

struct ModelChannel {
  const ChannelModel* channel = nullptr;
  std::vector<double> nominal;
  std::vector<Effect> effects;
  std::vector<int> effect_lines;  // where each effect's name is in the file
};

// A parameter or effect name as a TOML key (what fit_model_toml writes, what this reads).
std::string model_key(const std::string& name);

// Throws config::ConfigError (file, line, key, allowed values); a channel named twice too.
std::vector<ModelChannel> load_augmented_model(const std::string& path);

// Throws config::ConfigError (file, line) for an effect the model puts on a channel that
// planter-fit never tries there with this recording's columns (a friction on the clamp, say):
// the replay would otherwise apply it where it means nothing.
void check_effects_belong(const std::string& path, const std::vector<ModelChannel>& model,
                          const Recording& r);

}  // namespace planter::analysis
