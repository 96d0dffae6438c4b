#include "apps/planter-can/bus_watch.h"

#include <algorithm>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/lss.h"

namespace planter::cantool {

double CobStats::rate_hz() const {
  if (count < 2 || last_ns <= first_ns) return 0.0;
  return static_cast<double>(count - 1) * 1e9 / static_cast<double>(last_ns - first_ns);
}

void BusWatch::on_frame(const hal::CanFrame& f, std::int64_t now_ns) {
  ++frames_;
  if (f.id & hal::CanFrame::kErrorFlag) {
    ++error_frames_;
    return;
  }
  if (!f.is_standard_data()) return;
  bits_ += static_cast<std::uint64_t>(hal::can_frame_bits(std::min<int>(f.dlc, 8)));
  const std::uint16_t cob = f.cob_id();
  CobStats& c = cobs_[cob];
  if (c.count == 0) {
    c.first_ns = now_ns;
  } else {
    c.max_gap_ns = std::max(c.max_gap_ns, now_ns - c.last_ns);
  }
  ++c.count;
  c.last_ns = now_ns;
  c.last = f;

  const auto fn = static_cast<std::uint16_t>(cob & 0x780);
  const auto id = static_cast<std::uint8_t>(cob & 0x7F);
  if (id == 0 || cob == canopen::kLssMasterCobId || cob == canopen::kLssSlaveCobId) return;
  if (fn == canopen::kSdoRequestBase || fn == 0x000) return;  // the master's frames
  for (auto base : canopen::kRpdoBase) {
    if (fn == base) return;
  }
  NodeSeen& n = nodes_[id];
  n.seen = true;
  if (fn == canopen::kHeartbeatBase && f.dlc >= 1) {
    const std::uint8_t state = f.data[0] & 0x7F;
    if (state == 0) {
      n.boot_up = true;
    } else {
      if (n.heartbeats > 0)
        n.max_heartbeat_gap_ns = std::max(n.max_heartbeat_gap_ns, now_ns - n.last_heartbeat_ns);
      if (n.heartbeats == 0) n.first_heartbeat_ns = now_ns;
      ++n.heartbeats;
      n.last_heartbeat_ns = now_ns;
    }
    n.state = state;
  } else if (fn == canopen::kEmcyBase && f.dlc >= 2) {
    ++n.emcy_count;
    n.last_emcy_code = static_cast<std::uint16_t>(f.data[0] | (f.data[1] << 8));
  } else {
    for (auto base : canopen::kTpdoBase) {
      if (fn == base) ++n.pdo_frames;
    }
  }
}

double BusWatch::bus_load_pct(std::uint32_t bitrate_bps, std::int64_t now_ns) const {
  const std::int64_t span = now_ns - start_ns_;
  if (span <= 0 || bitrate_bps == 0) return 0.0;
  return 100.0 * static_cast<double>(bits_) /
         (static_cast<double>(bitrate_bps) * 1e-9 * static_cast<double>(span));
}

}  // namespace planter::cantool
