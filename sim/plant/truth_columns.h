#pragma once
// The simulator's ground truth as recording columns: what no sensor on the machine sees
// (docs/recording-format.md, "The simulator's ground truth"). Declared once here; the
// recording writer, planter-sim devices' truth file and the signal table's test derive from it.
#include <array>
#include <string>
#include <string_view>

#include "sim/plant/plant.h"

namespace planter::sim {

struct TruthColumn {
  std::string_view column;
  std::string_view unit;
  std::string_view what;
  int decimals;
  double PlantTruth::*value;
};

inline constexpr std::array kTruthColumns = {
    TruthColumn{"v_ground", "m/s", "the true ground speed", 5, &PlantTruth::v_mps},
    TruthColumn{"true_x_m", "m", "distance travelled", 5, &PlantTruth::x_m},
    TruthColumn{"true_sigma", "1", "R*omega / v from the true speeds", 4, &PlantTruth::sigma},
    TruthColumn{"true_omega", "rad/s", "the disc's true speed", 5, &PlantTruth::disc_omega_radps},
    TruthColumn{"true_clamp_force", "N", "the true clamping force", 2, &PlantTruth::clamp_force_N},
    TruthColumn{"true_depth_mm", "mm", "the true furrow depth", 3, &PlantTruth::depth_mm},
    TruthColumn{"true_slip", "1", "the soil wheel's slip", 4, &PlantTruth::slip},
};

// "v_ground,true_x_m,...": the truth columns' part of a header line, in order.
inline std::string truth_header() {
  std::string h;
  for (const TruthColumn& c : kTruthColumns) {
    if (!h.empty()) h += ',';
    h += c.column;
  }
  return h;
}

}  // namespace planter::sim
