#pragma once
// Turns one CAN frame into what it means on this machine: the service (NMT, SYNC, EMCY,
// PDO, SDO, heartbeat, LSS), the node, and the text a technician reads, with object names and
// engineering units when the board file says what the PDOs carry. Never trusts the frame:
// every length is checked (it is a fuzz target).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "firmware/controller/controller_config.h"
#include "planter/hal/can_frame.h"

namespace planter::cantool {

enum class Service : std::uint8_t {
  kNmt,
  kSync,
  kEmcy,
  kTpdo,
  kRpdo,
  kSdoRequest,
  kSdoResponse,
  kHeartbeat,
  kLssMaster,
  kLssSlave,
  kOther,
  kErrorFrame,
  kExtended,
  kRemote,
};
const char* service_name(Service s);

struct ProcessValue {
  std::uint16_t index = 0;
  std::uint8_t sub = 0;
  std::string name;  // object name, e.g. "velocity actual"
  std::int64_t raw = 0;
  double value = 0.0;     // in `unit` (raw when no scaling is known)
  std::string_view unit;  // static text
};

struct DecodedFrame {
  Service service = Service::kOther;
  std::uint8_t node = 0;             // 0 when the service has none
  int pdo = 0;                       // 1-4 for PDOs
  std::string node_name;             // board role ("disc_drive") when known
  std::string text;                  // one line
  std::vector<ProcessValue> values;  // PDOs decoded with the board's maps
  bool malformed = false;            // wrong length for its service
};

// A value in the machine's units: counts -> rad or mm, per mille -> N*m or N, 0.1 N -> N.
std::optional<ProcessValue> scale_process_value(const NodeConfig& node, std::uint16_t index,
                                                std::uint8_t sub, std::int64_t raw);

class FrameDecoder {
 public:
  // `board` may be null: PDOs are then shown as raw bytes.
  explicit FrameDecoder(const ControllerConfig* board) : board_(board) {}
  [[nodiscard]] DecodedFrame decode(const hal::CanFrame& frame) const;
  [[nodiscard]] const NodeConfig* node_config(std::uint8_t node_id) const;

 private:
  void decode_pdo(const hal::CanFrame& f, DecodedFrame& out, bool transmit, int k) const;
  const ControllerConfig* board_;
};

// "601  [8]  40 00 10 00 00 00 00 00" style raw text.
std::string raw_frame_text(const hal::CanFrame& frame);

}  // namespace planter::cantool
