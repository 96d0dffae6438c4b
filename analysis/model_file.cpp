#include "analysis/model_file.h"

#include <algorithm>
#include <cctype>

#include "config/toml_section.h"

namespace planter::analysis {
namespace {

const EffectSpec* spec_named(const std::string& name) {
  for (int k = 0; k <= static_cast<int>(EffectKind::kStiction); ++k) {
    const EffectSpec& s = effect_spec(static_cast<EffectKind>(k));
    if (s.name == name) return &s;
  }
  return nullptr;
}

}  // namespace

std::string model_key(const std::string& name) {
  std::string out;
  for (char c : name) out += (std::isalnum(static_cast<unsigned char>(c)) ? c : '_');
  return out;
}

std::vector<ModelChannel> load_augmented_model(const std::string& path) {
  config::TomlDocument doc(path);
  config::TomlSection root = doc.root();
  std::vector<ModelChannel> out;
  for (auto& t : root.array_of_tables("channel")) {
    ModelChannel m;
    const std::string output = t.string("output", "");
    for (const ChannelModel* ch : all_channels())
      if (ch->output() == output) m.channel = ch;
    if (!m.channel) t.fail("output", "'" + output + "' is no channel planter-fit knows");
    for (const ModelChannel& before : out)
      if (before.channel == m.channel)
        t.fail("output", "'" + output + "' has a [[channel]] table already: one per channel");
    (void)t.string("subsystem", "");
    for (const ParamSpec& p : m.channel->nominal_params())
      m.nominal.push_back(t.required_number(model_key(p.name), p.lower, p.upper, p.unit.c_str()));
    for (auto& e : t.array_of_tables("effect")) {
      const std::string name = e.string("name", "");
      const EffectSpec* spec = spec_named(name);
      if (!spec) e.fail("name", "'" + name + "' is no effect of the library");
      Effect fx{spec, {}};
      m.effect_lines.push_back(e.line_of("name"));
      for (const ParamSpec& p : spec->params) {
        // Grid ones, and those bounded relative to the output's size, scale with the data.
        const bool scales = p.of_output_size || !(p.upper > p.lower);
        const double lo = p.of_output_size && p.lower < 0.0 ? -1e9 : p.lower;
        const double hi = scales ? 1e9 : p.upper;
        fx.values.push_back(e.required_number(model_key(p.name), lo, hi, p.unit.c_str()));
      }
      e.reject_unknown_keys();
      m.effects.push_back(fx);
    }
    t.reject_unknown_keys();
    out.push_back(std::move(m));
  }
  root.reject_unknown_keys();
  if (out.empty()) throw config::ConfigError(path, 1, "channel", "no [[channel]] table");
  return out;
}

void check_effects_belong(const std::string& path, const std::vector<ModelChannel>& model,
                          const Recording& r) {
  for (const ModelChannel& m : model) {
    const std::vector<const EffectSpec*> tried = m.channel->candidates(r);
    for (std::size_t i = 0; i < m.effects.size(); ++i) {
      if (std::find(tried.begin(), tried.end(), m.effects[i].spec) != tried.end()) continue;
      std::string names;
      for (const EffectSpec* s : tried) names += (names.empty() ? "" : ", ") + s->name;
      throw config::ConfigError(path, i < m.effect_lines.size() ? m.effect_lines[i] : 0, "name",
                                "'" + m.effects[i].spec->name + "' is not an effect of channel '" +
                                    m.channel->output() +
                                    "' (with this recording's columns it takes: " + names + ")");
    }
  }
}

}  // namespace planter::analysis
