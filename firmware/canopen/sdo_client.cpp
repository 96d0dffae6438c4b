#include "firmware/canopen/sdo_client.h"

#include <algorithm>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/le_bytes.h"
#include "firmware/canopen/sdo_payload.h"

namespace planter::canopen {
namespace {}  // namespace

SdoClient::SdoClient(std::uint8_t node_id, std::int64_t timeout_ns)
    : node_id_(node_id), timeout_ns_(timeout_ns) {}

bool SdoClient::start_read(std::uint16_t index, std::uint8_t sub, std::span<std::uint8_t> buffer,
                           std::int64_t now_ns, hal::CanBus& bus) {
  if (status_ == SdoStatus::kBusy) return false;
  index_ = index;
  sub_ = sub;
  read_buffer_ = buffer;
  bytes_read_ = 0;
  abort_code_ = 0;
  toggle_ = false;
  phase_ = Phase::kUploadInit;
  status_ = SdoStatus::kBusy;
  deadline_ns_ = now_ns + timeout_ns_;
  send_request(sdo_mux_payload(0x40, index, sub), bus);
  return true;
}

bool SdoClient::start_write(std::uint16_t index, std::uint8_t sub,
                            std::span<const std::uint8_t> data, std::int64_t now_ns,
                            hal::CanBus& bus) {
  if (status_ == SdoStatus::kBusy || data.size() > kMaxDownloadBytes || data.empty()) return false;
  index_ = index;
  sub_ = sub;
  std::copy(data.begin(), data.end(), write_data_.begin());
  write_size_ = data.size();
  write_offset_ = 0;
  abort_code_ = 0;
  toggle_ = false;
  status_ = SdoStatus::kBusy;
  deadline_ns_ = now_ns + timeout_ns_;
  if (write_size_ <= 4) {
    // Expedited: e = 1, s = 1, n = number of unused bytes.
    auto payload =
        sdo_mux_payload(static_cast<std::uint8_t>(0x23 | ((4 - write_size_) << 2)), index, sub);
    std::copy(data.begin(), data.end(), payload.begin() + 4);
    phase_ = Phase::kDownloadInit;
    send_request(payload, bus);
  } else {
    auto payload = sdo_mux_payload(0x21, index, sub);  // segmented, size indicated
    const auto size = static_cast<std::uint32_t>(write_size_);
    for (int i = 0; i < 4; ++i) payload[4 + i] = static_cast<std::uint8_t>(size >> (8 * i));
    phase_ = Phase::kDownloadInit;
    send_request(payload, bus);
  }
  return true;
}

bool SdoClient::start_write_u32(std::uint16_t index, std::uint8_t sub, std::uint32_t value,
                                std::size_t size, std::int64_t now_ns, hal::CanBus& bus) {
  std::array<std::uint8_t, 4> bytes{};
  for (std::size_t i = 0; i < 4; ++i) bytes[i] = static_cast<std::uint8_t>(value >> (8 * i));
  return start_write(index, sub,
                     std::span<const std::uint8_t>(bytes.data(), std::min<std::size_t>(size, 4)),
                     now_ns, bus);
}

std::uint64_t SdoClient::value() const {
  std::uint64_t v = 0;
  const std::size_t n = std::min<std::size_t>(bytes_read_, 8);
  for (std::size_t i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(read_buffer_[i]) << (8 * i);
  return v;
}

bool SdoClient::accept_upload_data(const std::uint8_t* data, std::size_t count) {
  if (bytes_read_ + count > read_buffer_.size()) return false;
  std::copy(data, data + count, read_buffer_.begin() + static_cast<std::ptrdiff_t>(bytes_read_));
  bytes_read_ += count;
  return true;
}

bool SdoClient::on_frame(const hal::CanFrame& frame, std::int64_t now_ns, hal::CanBus& bus) {
  if (!frame.is_standard_data() || frame.cob_id() != kSdoResponseBase + node_id_) return false;
  if (status_ != SdoStatus::kBusy) return true;  // a late or stray response: ours, ignored
  if (frame.dlc < 1) return true;
  const std::uint8_t cmd = frame.data[0];
  const auto& d = frame.data;
  const bool has_mux = frame.dlc >= 4;
  const bool mux_matches = has_mux && (d[1] | (d[2] << 8)) == index_ && d[3] == sub_;

  if (cmd == 0x80) {  // abort from the server
    finish(SdoStatus::kAborted, frame.dlc >= 8 ? read_le_u32(&d[4]) : abort_code::kGeneral);
    return true;
  }
  deadline_ns_ = now_ns + timeout_ns_;  // every valid step restarts the timeout
  switch (phase_) {
    case Phase::kUploadInit: {
      if ((cmd & 0xE0) != 0x40 || !mux_matches) break;
      if ((cmd & 0x02) != 0) {  // expedited
        std::size_t n = 4;
        if ((cmd & 0x01) != 0) n = 4 - ((cmd >> 2) & 0x03);
        // Accept short frames: take only the bytes that arrived.
        n = std::min<std::size_t>(n, frame.dlc > 4 ? static_cast<std::size_t>(frame.dlc - 4) : 0);
        if (!accept_upload_data(&d[4], n)) {
          send_abort(abort_code::kLength, bus);
          finish(SdoStatus::kAborted, abort_code::kLength);
        } else {
          finish(SdoStatus::kDone);
        }
        return true;
      }
      if ((cmd & 0x01) != 0 && frame.dlc >= 8 && read_le_u32(&d[4]) > read_buffer_.size()) {
        send_abort(abort_code::kLength, bus);
        finish(SdoStatus::kAborted, abort_code::kLength);
        return true;
      }
      phase_ = Phase::kUploadSegment;
      toggle_ = false;
      send_request({0x60, 0, 0, 0, 0, 0, 0, 0}, bus);
      return true;
    }
    case Phase::kUploadSegment: {
      if ((cmd & 0xE0) != 0x00) break;
      if (((cmd & 0x10) != 0) != toggle_) {
        send_abort(abort_code::kToggleBit, bus);
        finish(SdoStatus::kAborted, abort_code::kToggleBit);
        return true;
      }
      std::size_t n = 7 - ((cmd >> 1) & 0x07);
      n = std::min<std::size_t>(n, frame.dlc > 1 ? static_cast<std::size_t>(frame.dlc - 1) : 0);
      if (!accept_upload_data(&d[1], n)) {
        send_abort(abort_code::kLength, bus);
        finish(SdoStatus::kAborted, abort_code::kLength);
        return true;
      }
      if ((cmd & 0x01) != 0) {
        finish(SdoStatus::kDone);
        return true;
      }
      toggle_ = !toggle_;
      send_request({static_cast<std::uint8_t>(0x60 | (toggle_ ? 0x10 : 0)), 0, 0, 0, 0, 0, 0, 0},
                   bus);
      return true;
    }
    case Phase::kDownloadInit: {
      if (cmd != 0x60 || !mux_matches) break;
      if (write_size_ <= 4) {
        finish(SdoStatus::kDone);
        return true;
      }
      phase_ = Phase::kDownloadSegment;
      toggle_ = false;
      send_next_download_segment(bus);
      return true;
    }
    case Phase::kDownloadSegment: {
      if ((cmd & 0xEF) != 0x20) break;
      if (((cmd & 0x10) != 0) != toggle_) {
        send_abort(abort_code::kToggleBit, bus);
        finish(SdoStatus::kAborted, abort_code::kToggleBit);
        return true;
      }
      if (write_offset_ >= write_size_) {
        finish(SdoStatus::kDone);
        return true;
      }
      toggle_ = !toggle_;
      send_next_download_segment(bus);
      return true;
    }
    case Phase::kNone:
      break;
  }
  // Anything else is a protocol violation: abort the transfer cleanly.
  send_abort(abort_code::kBadCommand, bus);
  finish(SdoStatus::kAborted, abort_code::kBadCommand);
  return true;
}

void SdoClient::send_next_download_segment(hal::CanBus& bus) {
  std::array<std::uint8_t, 8> payload{};
  const std::size_t n = std::min<std::size_t>(7, write_size_ - write_offset_);
  const bool last = write_offset_ + n >= write_size_;
  payload[0] = static_cast<std::uint8_t>((toggle_ ? 0x10 : 0) | ((7 - n) << 1) | (last ? 1 : 0));
  std::copy_n(write_data_.begin() + static_cast<std::ptrdiff_t>(write_offset_), n,
              payload.begin() + 1);
  write_offset_ += n;
  send_request(payload, bus);
}

void SdoClient::poll(std::int64_t now_ns, hal::CanBus& bus) {
  if (status_ == SdoStatus::kBusy && now_ns >= deadline_ns_) {
    send_abort(abort_code::kTimeout, bus);
    finish(SdoStatus::kTimedOut, abort_code::kTimeout);
  }
}

void SdoClient::send_request(const std::array<std::uint8_t, 8>& payload, hal::CanBus& bus) {
  hal::CanFrame frame{};
  frame.id = kSdoRequestBase + node_id_;
  frame.dlc = 8;
  frame.data = payload;
  bus.send(frame);
}

void SdoClient::send_abort(std::uint32_t code, hal::CanBus& bus) {
  send_request(sdo_abort_payload(index_, sub_, code), bus);
}

void SdoClient::finish(SdoStatus status, std::uint32_t code) {
  status_ = status;
  abort_code_ = code;
  phase_ = Phase::kNone;
}

}  // namespace planter::canopen
