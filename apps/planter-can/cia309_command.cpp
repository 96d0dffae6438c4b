#include "apps/planter-can/cia309_command.h"

#include "config/input_file.h"

namespace planter::cantool {
namespace {

bool is_integer(const std::string& t) { return parse_integer(t).has_value(); }

}  // namespace

std::string Cia309Error::text() const {
  if (token_number == 0) return expected;
  return "token " + std::to_string(token_number) + " '" + config::excerpt(token) + "': expected " +
         expected;
}

std::vector<std::string> split_tokens(std::string_view line) {
  std::vector<std::string> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r')) ++i;
    if (i >= line.size()) break;
    std::string tok;
    if (line[i] == '"') {
      const std::size_t end = line.find('"', i + 1);
      const std::size_t stop = end == std::string_view::npos ? line.size() : end + 1;
      tok.assign(line.substr(i, stop - i));
      i = stop;
    } else {
      while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
        tok.push_back(line[i++]);
    }
    out.push_back(std::move(tok));
  }
  return out;
}

Cia309Parse parse_cia309(std::string_view line) {
  const auto tokens = split_tokens(line);
  if (tokens.empty())
    return Cia309Error{
        0, "", "an empty command: expected [seq] [net] node r|w|start|stop|preop|reset ..."};
  Cia309Command cmd;
  std::size_t i = 0;
  auto error = [&](std::size_t at, const std::string& expected) -> Cia309Parse {
    return Cia309Error{at + 1, at < tokens.size() ? tokens[at] : "<end of line>", expected};
  };
  if (tokens[0].size() >= 2 && tokens[0].front() == '[' && tokens[0].back() == ']') {
    const auto seq = parse_integer(tokens[0].substr(1, tokens[0].size() - 2));
    if (!seq || *seq < 0 || *seq > 0xFFFFFFFF) return error(0, "a sequence number [0-4294967295]");
    cmd.sequence = static_cast<std::uint32_t>(*seq);
    ++i;
  }
  // net is present when two numbers precede the command word.
  if (i + 1 < tokens.size() && is_integer(tokens[i]) && is_integer(tokens[i + 1])) {
    const auto net = parse_integer(tokens[i]);
    if (*net < 1 || *net > 0xFFFF) return error(i, "a network number from 1 to 65535");
    cmd.net = static_cast<std::uint16_t>(*net);
    ++i;
  }
  if (i >= tokens.size()) return error(i, "a node-ID from 1 to 127");
  const auto node = parse_integer(tokens[i]);
  if (!node || *node < 0 || *node > 127)
    return error(i, "a node-ID from 1 to 127 (0 = all, NMT only)");
  cmd.node = static_cast<std::uint8_t>(*node);
  ++i;
  if (i >= tokens.size()) return error(i, "a command: r, w, start, stop, preop or reset");
  const std::string& word = tokens[i];
  const std::size_t word_at = i++;
  auto finish_nmt = [&](canopen::NmtCommand c) -> Cia309Parse {
    if (i < tokens.size()) return error(i, "the end of the line");
    cmd.kind = Cia309Command::Kind::kNmt;
    cmd.nmt = c;
    return cmd;
  };
  if (word == "start") return finish_nmt(canopen::NmtCommand::kStart);
  if (word == "stop") return finish_nmt(canopen::NmtCommand::kStop);
  if (word == "preop" || word == "preoperational")
    return finish_nmt(canopen::NmtCommand::kPreOperational);
  if (word == "reset") {
    if (i >= tokens.size()) return error(i, "'node' or 'comm' after reset");
    const std::string& what = tokens[i++];
    if (what == "node") return finish_nmt(canopen::NmtCommand::kResetNode);
    if (what == "comm" || what == "communication")
      return finish_nmt(canopen::NmtCommand::kResetCommunication);
    return error(i - 1, "'node' or 'comm' after reset");
  }
  const bool read = word == "r" || word == "read";
  const bool write = word == "w" || word == "write";
  if (!read && !write) return error(word_at, "a command: r, w, start, stop, preop or reset");
  if (cmd.node == 0) return error(word_at - 1, "a node-ID from 1 to 127 (SDO needs one node)");
  cmd.kind = read ? Cia309Command::Kind::kRead : Cia309Command::Kind::kWrite;
  if (i >= tokens.size()) return error(i, "an object index from 0x0000 to 0xFFFF");
  const auto index = parse_integer(tokens[i]);
  if (!index || *index < 0 || *index > 0xFFFF)
    return error(i, "an object index from 0x0000 to 0xFFFF");
  cmd.index = static_cast<std::uint16_t>(*index);
  cmd.index_decimal = tokens[i].rfind("0x", 0) != 0 && tokens[i].rfind("0X", 0) != 0;
  ++i;
  if (i >= tokens.size()) return error(i, "a sub-index from 0 to 255");
  const auto sub = parse_integer(tokens[i]);
  if (!sub || *sub < 0 || *sub > 255) return error(i, "a sub-index from 0 to 255");
  cmd.sub = static_cast<std::uint8_t>(*sub);
  ++i;
  if (i < tokens.size()) {
    cmd.type = parse_value_type(tokens[i]);
    if (!cmd.type) return error(i, std::string("a data type: ") + value_type_names());
    ++i;
  } else if (write) {
    return error(i, std::string("a data type: ") + value_type_names());
  }
  if (read) {
    if (i < tokens.size()) return error(i, "the end of the line");
    return cmd;
  }
  if (i >= tokens.size())
    return error(i, std::string("a value of type ") + std::string(cmd.type->name));
  // A visible string may be written unquoted with spaces: take the rest of the line.
  std::string text = tokens[i];
  if (cmd.type->kind == ValueKind::kString || cmd.type->kind == ValueKind::kOctets) {
    for (std::size_t k = i + 1; k < tokens.size(); ++k) text += " " + tokens[k];
  } else if (i + 1 < tokens.size()) {
    return error(i + 1, "the end of the line");
  }
  std::string why;
  auto encoded = encode_value(*cmd.type, text, why);
  if (!encoded) return error(i, why);
  cmd.value = std::move(*encoded);
  return cmd;
}

}  // namespace planter::cantool
