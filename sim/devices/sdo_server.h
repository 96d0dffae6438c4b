#pragma once
// SDO server (device side): answers expedited and segmented transfers from its dictionary.
#include <array>
#include <cstdint>

#include "planter/hal/can_bus.h"
#include "sim/devices/object_dictionary.h"

namespace planter::canopen {

// The device's rules for a value written over SDO (CiA 301: PDO mapping, store signature;
// a profile's value ranges). Returns 0 to accept, or the SDO abort code that refuses it.
class SdoWriteRules {
 public:
  virtual ~SdoWriteRules() = default;
  [[nodiscard]] virtual std::uint32_t check_write(const ObjectEntry& entry,
                                                  std::uint64_t value) const = 0;
};

class SdoServer {
 public:
  // rules may be null: every write of the right length is then accepted.
  SdoServer(std::uint8_t node_id, ObjectDictionary& od, const SdoWriteRules* rules = nullptr)
      : node_id_(node_id), od_(od), rules_(rules) {}
  // Returns true when the frame was an SDO request for this node (answered or aborted).
  bool on_frame(const hal::CanFrame& frame, hal::CanBus& bus);
  void set_node_id(std::uint8_t node_id) { node_id_ = node_id; }
  // Counts writes so the device can react to reconfiguration.
  [[nodiscard]] std::uint32_t writes() const { return writes_; }

 private:
  // A request's fields: command byte, index, sub-index, and the whole payload.
  struct Request {
    std::uint8_t cmd;
    std::uint16_t index;
    std::uint8_t sub;
    const std::array<std::uint8_t, 8>& data;
  };
  void initiate_upload(const Request& q, hal::CanBus& bus);
  void upload_segment(const Request& q, hal::CanBus& bus);
  void initiate_download(const Request& q, hal::CanBus& bus);
  void download_segment(const Request& q, hal::CanBus& bus);
  void reply(const std::array<std::uint8_t, 8>& payload, hal::CanBus& bus);
  void abort(std::uint16_t index, std::uint8_t sub, std::uint32_t code, hal::CanBus& bus);
  // The entry, or nullptr after aborting with "no such object" or "no such sub-index".
  ObjectEntry* entry_or_abort(std::uint16_t index, std::uint8_t sub, hal::CanBus& bus);
  std::uint32_t write_value(ObjectEntry& entry, const std::uint8_t* data, std::size_t n);

  std::uint8_t node_id_;
  ObjectDictionary& od_;
  const SdoWriteRules* rules_;
  // Segmented transfer in progress.
  ObjectEntry* segment_entry_ = nullptr;
  bool segment_upload_ = false;
  bool toggle_ = false;
  std::size_t offset_ = 0;
  std::size_t total_ = 0;
  std::array<std::uint8_t, 64> buffer_{};
  std::uint32_t writes_ = 0;
};

}  // namespace planter::canopen
