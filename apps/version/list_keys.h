#pragma once
// --list-keys, the same on every program that reads configuration files: prints the key tables'
// reference (config/config_key.h) whole, then exits.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <span>
#include <string>

#include "config/config_key.h"

namespace planter::apps {

inline void add_list_keys_flag(CLI::App& app,
                               std::span<const std::span<const config::ConfigKey>> rows,
                               const std::string& files) {
  app.add_flag_callback(
      "--list-keys",
      [rows] {
        // The program's error handler names the program.
        if (!config::write_key_reference(stdout, rows))
          throw CLI::RuntimeError("cannot write the key reference to standard output", 1);
        throw CLI::Success();
      },
      "print every key of " + files + " (table, default, unit, range, meaning) and exit");
}

}  // namespace planter::apps
