#pragma once
// The simulator's ground truth as recording columns: what no sensor on the machine sees
// (docs/recording-format.md, "The simulator's ground truth"). Declared once here; the
// recording writer, planter-sim devices' truth file and the signal table's test derive from it.
#include <array>
#include <cstddef>
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
  // Written as a sensor on the bus would deliver it: kSensorPathTicks late, like the measured
  // columns it is an input beside (the known disturbances). The rest is the truth at the row's
  // own time.
  bool through_sensor_path = false;
};

// A measured column holds the plant's state of this many control ticks before its row: the
// device samples at the end of a tick's plant step, sends it at the next SYNC, and the
// controller's telemetry holds it after its receive phase of the tick after
// (test RecordingWriter.KnownDisturbancesAreAlignedWithTheMeasurements holds it to a run).
inline constexpr std::size_t kSensorPathTicks = 2;

inline constexpr std::array kTruthColumns = {
    TruthColumn{"v_ground", "m/s", "the true ground speed", 5, &PlantTruth::v_mps},
    TruthColumn{"true_x_m", "m", "distance travelled", 5, &PlantTruth::x_m},
    TruthColumn{"true_sigma", "1", "R*omega / v from the true speeds", 4, &PlantTruth::sigma},
    TruthColumn{"true_omega", "rad/s", "the disc's true speed", 5, &PlantTruth::disc_omega_radps},
    TruthColumn{"true_clamp_force", "N", "the true clamping force", 2, &PlantTruth::clamp_force_N},
    TruthColumn{"true_depth_mm", "mm", "the true furrow depth", 3, &PlantTruth::depth_mm},
    TruthColumn{"true_slip", "1", "the soil wheel's slip", 4, &PlantTruth::slip},
    // Known disturbances: what the scenario varies on purpose, carried so that planter-fit takes
    // them as inputs and names only what is missing beyond them (issue 32). A field log has
    // them only where the machine measures them (a radar's speed gives the slip).
    TruthColumn{"known_slip", "1",
                "the soil's slip about its mean, as the scenario varies it along the row", 5,
                &PlantTruth::known_slip, true},
    TruthColumn{"known_terrain_depth_mm", "mm", "the depth the terrain adds to the furrow", 3,
                &PlantTruth::known_terrain_depth_mm, true},
    TruthColumn{"known_nip_mm", "mm", "the seedling's thickness in the clamp's nip", 3,
                &PlantTruth::known_nip_mm, true},
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
