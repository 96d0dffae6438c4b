#pragma once
// Blocking SDO transfers for the tool, on the firmware's own non-blocking SdoClient. Frames
// that are not the awaited response (heartbeats, PDOs, other nodes) go to an observer so a
// scan or a check keeps listening while it asks.
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "apps/planter-can/tool_link.h"

namespace planter::cantool {

struct SdoResult {
  enum class Status : std::uint8_t { kOk, kAborted, kTimedOut };
  Status status = Status::kOk;
  std::uint32_t abort_code = 0;
  std::vector<std::uint8_t> data;  // uploaded bytes (reads)

  [[nodiscard]] bool ok() const { return status == Status::kOk; }
  [[nodiscard]] std::uint64_t value() const;  // little-endian, first 8 bytes
  // "timeout: no answer from node 7 in 100 ms" or "abort 0x06020000: object does not exist".
  [[nodiscard]] std::string error_text(std::uint8_t node_id, std::int64_t timeout_ns) const;
};

class SdoSession {
 public:
  using Observer = std::function<void(const hal::CanFrame&, std::int64_t now_ns)>;
  static constexpr std::size_t kMaxUploadBytes = 1024;

  SdoSession(ToolLink& link, std::int64_t timeout_ns) : link_(link), timeout_ns_(timeout_ns) {}
  void set_observer(Observer observer) { observer_ = std::move(observer); }

  SdoResult read(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub);
  SdoResult write(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub,
                  std::span<const std::uint8_t> data);
  SdoResult write_u32(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub,
                      std::uint32_t value, std::size_t size);
  [[nodiscard]] std::int64_t timeout_ns() const { return timeout_ns_; }
  [[nodiscard]] std::uint64_t round_trips() const { return round_trips_; }

 private:
  template <typename Start>
  SdoResult run(std::uint8_t node_id, Start start, std::span<std::uint8_t> buffer);

  ToolLink& link_;
  std::int64_t timeout_ns_;
  Observer observer_;
  std::uint64_t round_trips_ = 0;
};

}  // namespace planter::cantool
