#include "sim/devices/sdo_server.h"

#include <algorithm>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/sdo_payload.h"

namespace planter::canopen {

bool SdoServer::on_frame(const hal::CanFrame& frame, hal::CanBus& bus) {
  if (!frame.is_standard_data() || frame.cob_id() != kSdoRequestBase + node_id_) return false;
  if (frame.dlc != 8) {
    abort(0, 0, abort_code::kBadCommand, bus);
    return true;
  }
  const auto& d = frame.data;
  const Request q{d[0], static_cast<std::uint16_t>(d[1] | (d[2] << 8)), d[3], d};
  // The client's command specifier (CiA 301, 7.2.4.3), the top three bits.
  switch (q.cmd == 0x80 ? -1 : q.cmd >> 5) {
    case -1:  // client abort
      segment_entry_ = nullptr;
      break;
    case 2:
      initiate_upload(q, bus);
      break;
    case 3:
      upload_segment(q, bus);
      break;
    case 1:
      initiate_download(q, bus);
      break;
    case 0:
      download_segment(q, bus);
      break;
    default:
      abort(q.index, q.sub, abort_code::kBadCommand, bus);
  }
  return true;
}

// An initiate upload: expedited for up to 4 bytes, else the first of a segmented one.
void SdoServer::initiate_upload(const Request& q, hal::CanBus& bus) {
  segment_entry_ = nullptr;
  ObjectEntry* e = entry_or_abort(q.index, q.sub, bus);
  if (e == nullptr) return;
  if (e->access == Access::kWriteOnly) {
    abort(q.index, q.sub, abort_code::kWriteOnly, bus);
    return;
  }
  std::array<std::uint8_t, 8> r = sdo_mux_payload(0, q.index, q.sub);
  if (e->size > 0 && e->size <= 4) {
    r[0] = static_cast<std::uint8_t>(0x43 | ((4 - e->size) << 2));
    for (int i = 0; i < e->size; ++i) r[4 + i] = static_cast<std::uint8_t>(e->value >> (8 * i));
    reply(r, bus);
    return;
  }
  // Segmented: strings and 8-byte values.
  total_ = e->size == 0 ? std::min(e->text.size(), buffer_.size()) : e->size;
  if (e->size == 0) {
    std::copy_n(e->text.begin(), total_, buffer_.begin());
  } else {
    for (std::size_t i = 0; i < total_; ++i)
      buffer_[i] = static_cast<std::uint8_t>(e->value >> (8 * i));
  }
  segment_entry_ = e;
  segment_upload_ = true;
  toggle_ = false;
  offset_ = 0;
  r[0] = 0x41;
  for (int i = 0; i < 4; ++i) r[4 + i] = static_cast<std::uint8_t>(total_ >> (8 * i));
  reply(r, bus);
}

// The next segment of an upload, its toggle checked.
void SdoServer::upload_segment(const Request& q, hal::CanBus& bus) {
  if (segment_entry_ == nullptr || !segment_upload_) {
    abort(q.index, q.sub, abort_code::kBadCommand, bus);
    return;
  }
  if (((q.cmd & 0x10) != 0) != toggle_) {
    abort(segment_entry_->index, segment_entry_->sub, abort_code::kToggleBit, bus);
    segment_entry_ = nullptr;
    return;
  }
  const std::size_t n = std::min<std::size_t>(7, total_ - offset_);
  const bool last = offset_ + n >= total_;
  std::array<std::uint8_t, 8> r{};
  r[0] = static_cast<std::uint8_t>((toggle_ ? 0x10 : 0) | ((7 - n) << 1) | (last ? 1 : 0));
  std::copy_n(buffer_.begin() + static_cast<std::ptrdiff_t>(offset_), n, r.begin() + 1);
  offset_ += n;
  toggle_ = !toggle_;
  if (last) segment_entry_ = nullptr;
  reply(r, bus);
}

// An initiate download: expedited (written at once), or the size of a segmented one.
void SdoServer::initiate_download(const Request& q, hal::CanBus& bus) {
  segment_entry_ = nullptr;
  ObjectEntry* e = entry_or_abort(q.index, q.sub, bus);
  if (e == nullptr) return;
  if (e->access == Access::kReadOnly || e->access == Access::kConst) {
    abort(q.index, q.sub, abort_code::kReadOnly, bus);
    return;
  }
  if ((q.cmd & 0x02) != 0) {  // expedited
    const std::size_t n = (q.cmd & 0x01) != 0 ? 4 - ((q.cmd >> 2) & 0x03) : 4;
    const std::uint32_t code = write_value(*e, &q.data[4], n);
    if (code != 0) {
      abort(q.index, q.sub, code, bus);
      return;
    }
    reply(sdo_mux_payload(0x60, q.index, q.sub), bus);
    return;
  }
  total_ = (q.cmd & 0x01) != 0 ? static_cast<std::size_t>(q.data[4] | (q.data[5] << 8) |
                                                          (q.data[6] << 16) | (q.data[7] << 24))
                               : 0;
  if (total_ == 0 || total_ > buffer_.size()) {
    abort(q.index, q.sub, abort_code::kLength, bus);
    return;
  }
  segment_entry_ = e;
  segment_upload_ = false;
  toggle_ = false;
  offset_ = 0;
  reply(sdo_mux_payload(0x60, q.index, q.sub), bus);
}

// The next segment of a download, written whole at the last.
void SdoServer::download_segment(const Request& q, hal::CanBus& bus) {
  if (segment_entry_ == nullptr || segment_upload_) {
    abort(q.index, q.sub, abort_code::kBadCommand, bus);
    return;
  }
  ObjectEntry& e = *segment_entry_;
  if (((q.cmd & 0x10) != 0) != toggle_) {
    abort(e.index, e.sub, abort_code::kToggleBit, bus);
    segment_entry_ = nullptr;
    return;
  }
  const std::size_t n = 7 - ((q.cmd >> 1) & 0x07);
  if (offset_ + n > total_) {
    abort(e.index, e.sub, abort_code::kLength, bus);
    segment_entry_ = nullptr;
    return;
  }
  std::copy_n(q.data.begin() + 1, n, buffer_.begin() + static_cast<std::ptrdiff_t>(offset_));
  offset_ += n;
  const bool last = (q.cmd & 0x01) != 0;
  if (last) {
    segment_entry_ = nullptr;
    const std::uint32_t code = write_value(e, buffer_.data(), offset_);
    if (code != 0) {
      abort(e.index, e.sub, code, bus);
      return;
    }
  }
  reply({static_cast<std::uint8_t>(0x20 | (toggle_ ? 0x10 : 0)), 0, 0, 0, 0, 0, 0, 0}, bus);
  toggle_ = !toggle_;
}

std::uint32_t SdoServer::write_value(ObjectEntry& entry, const std::uint8_t* data, std::size_t n) {
  if (entry.size == 0) {
    if (n > entry.text.capacity()) return abort_code::kLength;
    entry.text.assign(reinterpret_cast<const char*>(data), n);
  } else {
    if (n != entry.size) return abort_code::kLength;
    std::uint64_t v = 0;
    for (std::size_t i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(data[i]) << (8 * i);
    if (rules_ != nullptr) {
      if (const std::uint32_t code = rules_->check_write(entry, v); code != 0) return code;
    }
    od_.store(entry, v);
  }
  ++writes_;
  return 0;
}

ObjectEntry* SdoServer::entry_or_abort(std::uint16_t index, std::uint8_t sub, hal::CanBus& bus) {
  ObjectEntry* e = od_.find(index, sub);
  if (e == nullptr)
    abort(index, sub, od_.has_index(index) ? abort_code::kNoSubIndex : abort_code::kNoObject, bus);
  return e;
}

void SdoServer::reply(const std::array<std::uint8_t, 8>& payload, hal::CanBus& bus) {
  hal::CanFrame f{};
  f.id = kSdoResponseBase + node_id_;
  f.dlc = 8;
  f.data = payload;
  bus.send(f);
}

void SdoServer::abort(std::uint16_t index, std::uint8_t sub, std::uint32_t code, hal::CanBus& bus) {
  reply(sdo_abort_payload(index, sub, code), bus);
}

}  // namespace planter::canopen
