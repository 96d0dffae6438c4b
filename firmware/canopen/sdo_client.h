#pragma once
// Non-blocking SDO client for one server node: expedited and segmented upload and download.
// The caller feeds it frames and time; it never waits.
#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

#include "planter/hal/can_bus.h"

namespace planter::canopen {

enum class SdoStatus : std::uint8_t { kIdle, kBusy, kDone, kAborted, kTimedOut };

class SdoClient {
 public:
  static constexpr std::size_t kMaxDownloadBytes = 64;

  SdoClient(std::uint8_t node_id, std::int64_t timeout_ns);

  // Starts reading index:sub into `buffer`. False if a transfer is already running.
  bool start_read(std::uint16_t index, std::uint8_t sub, std::span<std::uint8_t> buffer,
                  std::int64_t now_ns, hal::CanBus& bus);
  // Starts writing `data` (copied) to index:sub. False if busy or data too long.
  bool start_write(std::uint16_t index, std::uint8_t sub, std::span<const std::uint8_t> data,
                   std::int64_t now_ns, hal::CanBus& bus);
  bool start_write_u32(std::uint16_t index, std::uint8_t sub, std::uint32_t value, std::size_t size,
                       std::int64_t now_ns, hal::CanBus& bus);

  // Offers a received frame; returns true when it was this client's response.
  bool on_frame(const hal::CanFrame& frame, std::int64_t now_ns, hal::CanBus& bus);
  // Detects the local timeout: sends an abort and ends the transfer.
  void poll(std::int64_t now_ns, hal::CanBus& bus);
  // Forgets a finished transfer so a new one can start.
  void reset() { status_ = SdoStatus::kIdle; }

  [[nodiscard]] SdoStatus status() const { return status_; }
  [[nodiscard]] std::uint32_t abort_code() const { return abort_code_; }
  [[nodiscard]] std::size_t bytes_read() const { return bytes_read_; }
  // The value read, little-endian, up to 8 bytes.
  [[nodiscard]] std::uint64_t value() const;
  [[nodiscard]] std::uint8_t node_id() const { return node_id_; }
  [[nodiscard]] std::uint16_t index() const { return index_; }
  [[nodiscard]] std::uint8_t sub_index() const { return sub_; }

 private:
  enum class Phase : std::uint8_t {
    kNone,
    kUploadInit,
    kUploadSegment,
    kDownloadInit,
    kDownloadSegment
  };

  void send_request(const std::array<std::uint8_t, 8>& payload, hal::CanBus& bus);
  void send_abort(std::uint32_t code, hal::CanBus& bus);
  void finish(SdoStatus status, std::uint32_t code = 0);
  void send_next_download_segment(hal::CanBus& bus);
  bool accept_upload_data(const std::uint8_t* data, std::size_t count);

  std::uint8_t node_id_;
  std::int64_t timeout_ns_;
  SdoStatus status_ = SdoStatus::kIdle;
  Phase phase_ = Phase::kNone;
  std::uint16_t index_ = 0;
  std::uint8_t sub_ = 0;
  std::uint32_t abort_code_ = 0;
  std::int64_t deadline_ns_ = 0;
  bool toggle_ = false;
  std::span<std::uint8_t> read_buffer_{};
  std::size_t bytes_read_ = 0;
  std::array<std::uint8_t, kMaxDownloadBytes> write_data_{};
  std::size_t write_size_ = 0;
  std::size_t write_offset_ = 0;
};

}  // namespace planter::canopen
