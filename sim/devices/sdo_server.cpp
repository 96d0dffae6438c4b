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
  const std::uint8_t cmd = d[0];
  const auto index = static_cast<std::uint16_t>(d[1] | (d[2] << 8));
  const std::uint8_t sub = d[3];
  const std::uint8_t ccs = cmd >> 5;

  if (cmd == 0x80) {  // client abort
    segment_entry_ = nullptr;
    return true;
  }
  if (ccs == 2) {  // initiate upload
    segment_entry_ = nullptr;
    ObjectEntry* e = entry_or_abort(index, sub, bus);
    if (e == nullptr) return true;
    if (e->access == Access::kWriteOnly) {
      abort(index, sub, abort_code::kWriteOnly, bus);
      return true;
    }
    std::array<std::uint8_t, 8> r = sdo_mux_payload(0, index, sub);
    if (e->size > 0 && e->size <= 4) {
      r[0] = static_cast<std::uint8_t>(0x43 | ((4 - e->size) << 2));
      for (int i = 0; i < e->size; ++i) r[4 + i] = static_cast<std::uint8_t>(e->value >> (8 * i));
      reply(r, bus);
      return true;
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
    return true;
  }
  if (ccs == 3) {  // upload segment
    if (segment_entry_ == nullptr || !segment_upload_) {
      abort(index, sub, abort_code::kBadCommand, bus);
      return true;
    }
    if (((cmd & 0x10) != 0) != toggle_) {
      abort(segment_entry_->index, segment_entry_->sub, abort_code::kToggleBit, bus);
      segment_entry_ = nullptr;
      return true;
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
    return true;
  }
  if (ccs == 1) {  // initiate download
    segment_entry_ = nullptr;
    ObjectEntry* e = entry_or_abort(index, sub, bus);
    if (e == nullptr) return true;
    if (e->access == Access::kReadOnly || e->access == Access::kConst) {
      abort(index, sub, abort_code::kReadOnly, bus);
      return true;
    }
    if ((cmd & 0x02) != 0) {  // expedited
      const std::size_t n = (cmd & 0x01) != 0 ? 4 - ((cmd >> 2) & 0x03) : 4;
      const std::uint32_t code = write_value(*e, &d[4], n);
      if (code != 0) {
        abort(index, sub, code, bus);
        return true;
      }
      reply(sdo_mux_payload(0x60, index, sub), bus);
      return true;
    }
    total_ = (cmd & 0x01) != 0
                 ? static_cast<std::size_t>(d[4] | (d[5] << 8) | (d[6] << 16) | (d[7] << 24))
                 : 0;
    if (total_ == 0 || total_ > buffer_.size()) {
      abort(index, sub, abort_code::kLength, bus);
      return true;
    }
    segment_entry_ = e;
    segment_upload_ = false;
    toggle_ = false;
    offset_ = 0;
    reply(sdo_mux_payload(0x60, index, sub), bus);
    return true;
  }
  if (ccs == 0) {  // download segment
    if (segment_entry_ == nullptr || segment_upload_) {
      abort(index, sub, abort_code::kBadCommand, bus);
      return true;
    }
    ObjectEntry& e = *segment_entry_;
    if (((cmd & 0x10) != 0) != toggle_) {
      abort(e.index, e.sub, abort_code::kToggleBit, bus);
      segment_entry_ = nullptr;
      return true;
    }
    const std::size_t n = 7 - ((cmd >> 1) & 0x07);
    if (offset_ + n > total_) {
      abort(e.index, e.sub, abort_code::kLength, bus);
      segment_entry_ = nullptr;
      return true;
    }
    std::copy_n(d.begin() + 1, n, buffer_.begin() + static_cast<std::ptrdiff_t>(offset_));
    offset_ += n;
    const bool last = (cmd & 0x01) != 0;
    if (last) {
      segment_entry_ = nullptr;
      const std::uint32_t code = write_value(e, buffer_.data(), offset_);
      if (code != 0) {
        abort(e.index, e.sub, code, bus);
        return true;
      }
    }
    reply({static_cast<std::uint8_t>(0x20 | (toggle_ ? 0x10 : 0)), 0, 0, 0, 0, 0, 0, 0}, bus);
    toggle_ = !toggle_;
    return true;
  }
  abort(index, sub, abort_code::kBadCommand, bus);
  return true;
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
