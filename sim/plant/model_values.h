#pragma once
// Every value of the plant's seedling, release, soil and strength models that a conclusion of
// the simulator rests on, declared once: its unit, where it comes from (the paper's section, a
// standard, the machine's design) or the word "assumed", and a plausible range. The report's
// assumptions, `planter-sim values` and the sensitivity analysis all read this table; a value
// itself lives in PlantConfig (its default there, a scenario may set it).
#include <span>
#include <string>

#include "sim/plant/plant_config.h"

namespace planter::sim {

enum class ValueOrigin { measured, design, assumed, calibrated };
const char* origin_name(ValueOrigin o);

struct ModelValue {
  const char* key;  // as the scenario file names it: "table.key"
  const char* unit;
  ValueOrigin origin;
  double low, high;  // plausible range
  const char* source;
  double& (*ref)(PlantConfig&);
  [[nodiscard]] double value(const PlantConfig& c) const {
    PlantConfig copy = c;  // ref may fill a default that follows from a measurement
    return ref(copy);
  }
};

std::span<const ModelValue> model_values();

// The table as text, one value a line (key, value, unit, range, origin, source).
std::string model_values_text(const PlantConfig& c);
// The same as an HTML table.
std::string model_values_html(const PlantConfig& c);

}  // namespace planter::sim
