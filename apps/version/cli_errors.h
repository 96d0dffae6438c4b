#pragma once
// How a command line's parse ends, the same in every program (issue 53, items 13 and 15):
// --help, --version and --list-keys written whole, or said failed with exit 1 (a full disk, a
// closed pipe); any other error one line naming the program, a subcommand's typo named as typed
// (its bytes escaped: a terminal is never sent what the user typed raw), exit `bad_input`.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <string>
#include <string_view>

namespace planter::apps {

// Printable ASCII as it is, every other byte as \xNN.
inline std::string escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x20 && u < 0x7f) {
      out += c;
    } else {
      char hex[5];
      std::snprintf(hex, sizeof hex, "\\x%02x", u);
      out += hex;
    }
  }
  return out;
}

inline int parse_ended(CLI::App& app, const CLI::ParseError& e, const char* program, int argc,
                       char** argv, int bad_input) {
  if (e.get_exit_code() == 0) {
    app.exit(e);
    std::cout.flush();
    if (!std::cout || std::fflush(stdout) != 0 || std::ferror(stdout)) {
      std::fprintf(stderr, "%s: cannot write to standard output\n", program);
      return 1;
    }
    return 0;
  }
  std::string why = escaped(e.what());
  // A word where a subcommand belongs that is none: CLI11 says only that one is required.
  const bool wants_subcommand = app.get_require_subcommand_min() > 0;
  if (wants_subcommand && app.get_subcommands().empty() && argc > 1 && argv[1][0] != '-')
    why = "'" + escaped(argv[1]) + "' is not a subcommand";
  if (dynamic_cast<const CLI::RuntimeError*>(&e) != nullptr) {  // --list-keys could not write
    std::fprintf(stderr, "%s: %s\n", program, why.c_str());
    return 1;
  }
  std::fprintf(stderr, "%s: %s (%s --help lists the %s)\n", program, why.c_str(), program,
               wants_subcommand ? "subcommands and options" : "options");
  return bad_input;
}

}  // namespace planter::apps
