#pragma once
// A figure in the console's JSON: the number, or null where it is not known (NaN, infinite),
// since JSON has no NaN and the page shows null as not known.
#include <cmath>
#include <nlohmann/json.hpp>

namespace planter::console {

inline nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

}  // namespace planter::console
