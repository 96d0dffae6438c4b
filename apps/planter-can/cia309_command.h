#pragma once
// The CiA 309-3 ASCII command grammar (as lely's coctl and CANopenNode's cocomm speak it):
//   [seq] [net] node r[ead] index sub [type]
//   [seq] [net] node w[rite] index sub type value
//   [seq] [net] node start | stop | preop | reset node | reset comm
// A parse error names the bad token and what was expected there.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "apps/planter-can/value_codec.h"
#include "firmware/canopen/cob_id.h"

namespace planter::cantool {

struct Cia309Command {
  enum class Kind : std::uint8_t { kRead, kWrite, kNmt };
  Kind kind = Kind::kRead;
  std::optional<std::uint32_t> sequence;
  std::uint16_t net = 1;
  std::uint8_t node = 0;  // 0 = all nodes (NMT only)
  std::uint16_t index = 0;
  bool index_decimal = false;  // written without 0x: CiA 309-3 reads it as decimal
  std::uint8_t sub = 0;
  std::optional<ValueType> type;    // reads may leave it to the object table
  std::vector<std::uint8_t> value;  // writes: encoded
  canopen::NmtCommand nmt = canopen::NmtCommand::kStart;
};

struct Cia309Error {
  std::size_t token_number = 0;  // 1-based; 0 = the line as a whole
  std::string token;
  std::string expected;
  [[nodiscard]] std::string text() const;
};

using Cia309Parse = std::variant<Cia309Command, Cia309Error>;
Cia309Parse parse_cia309(std::string_view line);
// Splits on whitespace; a double-quoted string is one token (quotes kept).
std::vector<std::string> split_tokens(std::string_view line);

}  // namespace planter::cantool
