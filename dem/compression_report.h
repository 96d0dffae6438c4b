#pragma once
// What `planter-dem compress` writes: curve.csv, result.json, params.toml and a
// self-contained report.html with the force-displacement plot.
#include <string>

#include "config/output_set.h"
#include "dem/compression_test.h"

namespace planter::dem {

struct CompressionRun {
  CompressionSetup setup;
  CompressionResult result;
  double wall_s = 0.0;
};

// Throws std::runtime_error naming the file when one cannot be written.
// Writes curve.csv, result.json, params.toml and report.html into the set and commits it.
void write_compression_outputs(config::OutputSet& out, const CompressionRun& run);
// result.json's content (also one line of a calibration's run cache).
std::string compression_result_json(const CompressionRun& run);

}  // namespace planter::dem
