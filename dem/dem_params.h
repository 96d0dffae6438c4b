#pragma once
// The compression test's parameters as a TOML file (planter-dem --params): every key has the
// paper's value as its default and an allowed range; a bad file is one ConfigError.
#include <string>

#include "dem/compression_test.h"

namespace planter::dem {

// Reads `path` over the defaults. Throws config::ConfigError (file, line, key, range).
CompressionSetup load_compression_setup(const std::string& path);
// The same keys as TOML text (what `planter-dem compress` stores beside its results).
std::string compression_setup_toml(const CompressionSetup& s);

}  // namespace planter::dem
