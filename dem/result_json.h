#pragma once
// A compression's figures as every JSON of it names them: result.json of `planter-dem compress`
// (compression_report.cpp) and the calibration's kept runs (calibration_runs.cpp). Each adds
// the peak's displacement in its own unit. Inside planter_dem_tools only (nlohmann is private).
#include <nlohmann/json.hpp>

#include "dem/compression_test.h"

namespace planter::dem {

inline void put_result_figures(nlohmann::json& j, const CompressionResult& r) {
  j["peak_force_N"] = r.peak_force_N;
  j["first_peak_found"] = r.first_peak_found;
  j["broken_bonds"] = r.broken_bonds;
  j["particles"] = r.particles;
  j["bonds"] = r.bonds;
  j["steps"] = r.steps;
  j["max_kinetic_to_work"] = r.max_kinetic_to_work;
}

}  // namespace planter::dem
