// Fuzz target: the text the tool takes from people and files: CiA 309-3 command lines and
// candump log lines. Every input either parses or yields an error message.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "apps/planter-can/candump_log.h"
#include "apps/planter-can/cia309_command.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace planter::cantool;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  const Cia309Parse p = parse_cia309(text);
  if (const auto* e = std::get_if<Cia309Error>(&p)) {
    if (e->text().empty()) __builtin_trap();  // an error always says something
  }
  const LogParse l = parse_log_line(text);
  if (l.kind == LogLineKind::kError && l.error.empty()) __builtin_trap();
  if (l.kind == LogLineKind::kFrame && l.record.frame.dlc > 8) __builtin_trap();
  return 0;
}
