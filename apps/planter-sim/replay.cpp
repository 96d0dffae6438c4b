#include "apps/planter-sim/replay.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "analysis/model_file.h"
#include "config/output_set.h"

namespace planter::sim {

int run_replay(const std::string& model_path, const std::string& recording_path,
               const std::string& out_dir, bool force) {
  using namespace analysis;
  // The output folder is checked first: a refusal after all the work would waste it.
  config::OutputSet out(out_dir, "planter-sim replay", force);
  const std::vector<ModelChannel> model = load_augmented_model(model_path);
  const Recording rec = load_recording(recording_path);
  check_effects_belong(model_path, model, rec);
  std::vector<const ModelChannel*> used;
  std::vector<std::vector<double>> sims;
  for (const auto& m : model) {
    bool ok = true;
    for (const auto& c : m.channel->needs()) ok = ok && rec.has(c);
    if (!ok) {
      std::printf("%-12s not in the recording: skipped\n", m.channel->output().c_str());
      continue;
    }
    std::vector<double> y;
    m.channel->simulate(rec, m.nominal, m.effects, y);
    const auto& meas = rec.at(m.channel->output());
    double ss = 0;
    for (std::size_t k = 0; k < y.size(); ++k) ss += (y[k] - meas[k]) * (y[k] - meas[k]);
    const double rms = std::sqrt(ss / static_cast<double>(y.size()));
    if (!std::isfinite(rms))
      throw RecordingError(recording_path, 0,
                           "column '" + m.channel->output() +
                               "': its values overflow the model (a cell far outside the "
                               "machine's range?); nothing written");
    std::printf("%-12s %zu effect(s), RMS error %.4g\n", m.channel->output().c_str(),
                m.effects.size(), rms);
    used.push_back(&m);
    sims.push_back(std::move(y));
  }
  if (used.empty())
    throw RecordingError(recording_path, 0,
                         "has none of the model's channels; nothing to replay, nothing written");
  std::ostringstream csv;
  csv << "t";
  for (const auto* m : used)
    csv << ',' << m->channel->output() << ',' << m->channel->output() << "_sim";
  csv << '\n';
  char cell[32];
  for (std::size_t k = 0; k < rec.size(); ++k) {
    std::snprintf(cell, sizeof cell, "%.3f", rec.t[k]);
    csv << cell;
    for (std::size_t c = 0; c < used.size(); ++c) {
      std::snprintf(cell, sizeof cell, ",%.6g,%.6g", rec.at(used[c]->channel->output())[k],
                    sims[c][k]);
      csv << cell;
    }
    csv << '\n';
  }
  out.write("replay.csv", csv.str());
  out.commit();
  std::printf("wrote %s/replay.csv\n", out_dir.c_str());
  return 0;
}

}  // namespace planter::sim
