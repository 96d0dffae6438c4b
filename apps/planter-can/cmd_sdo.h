#pragma once
// `sdo`: CiA 309-3 lines from the command line or a batch file (-f); `nmt`: NMT commands,
// confirmed by the nodes' heartbeats when they send them.
#include <string>
#include <vector>

#include "apps/planter-can/cia309_command.h"
#include "apps/planter-can/tool_context.h"

namespace planter::cantool {

struct SdoLine {
  std::string source;  // "file.txt:3" or "command line"
  std::string text;
};

// Reads a batch file: one command per line, '#' comments and blank lines skipped.
// False (and `error` set) when the file cannot be read.
bool read_batch_file(const std::string& path, std::vector<SdoLine>& lines, std::string& error);
int run_sdo(ToolContext& ctx, const std::vector<SdoLine>& lines);
// Executes one parsed command; returns the reply text ("OK", a value, "ERROR: ...").
std::string execute_cia309(ToolContext& ctx, const Cia309Command& cmd, bool& ok);

int run_nmt(ToolContext& ctx, const std::string& command, const std::string& node);

}  // namespace planter::cantool
