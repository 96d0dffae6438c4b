#include "apps/planter-can/sdo_session.h"

#include <array>
#include <cstdio>

#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/sdo_client.h"

namespace planter::cantool {

std::uint64_t SdoResult::value() const {
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < data.size() && i < 8; ++i) v |= std::uint64_t{data[i]} << (8 * i);
  return v;
}

std::string SdoResult::error_text(std::uint8_t node_id, std::int64_t timeout_ns) const {
  char buf[160];
  switch (status) {
    case Status::kOk:
      return "ok";
    case Status::kTimedOut:
      std::snprintf(buf, sizeof buf, "timeout: no answer from node %u in %lld ms", node_id,
                    static_cast<long long>(timeout_ns / 1'000'000));
      return buf;
    case Status::kAborted:
      break;
  }
  std::snprintf(buf, sizeof buf, "abort 0x%08X: %s", abort_code,
                canopen::abort_code_text(abort_code));
  return buf;
}

template <typename Start>
SdoResult SdoSession::run(std::uint8_t node_id, Start start, std::span<std::uint8_t> buffer) {
  canopen::SdoClient client(node_id, timeout_ns_);
  SdoResult result;
  // A late answer to an earlier, aborted transfer must not be taken for this one's.
  hal::CanFrame stale;
  while (link_.receive(stale)) {
    if (observer_) observer_(stale, link_.now_ns());
  }
  if (!start(client)) {
    result.status = SdoResult::Status::kAborted;
    result.abort_code = canopen::abort_code::kLength;
    return result;
  }
  ++round_trips_;
  hal::CanFrame frame;
  while (client.status() == canopen::SdoStatus::kBusy) {
    const std::int64_t now = link_.now_ns();
    client.poll(now, link_);
    if (client.status() != canopen::SdoStatus::kBusy) break;
    if (!link_.receive_until(frame, now + timeout_ns_)) continue;  // poll() sees the timeout
    const std::int64_t t = link_.now_ns();
    if (!client.on_frame(frame, t, link_) && observer_) observer_(frame, t);
  }
  switch (client.status()) {
    case canopen::SdoStatus::kDone:
      result.data.assign(buffer.begin(),
                         buffer.begin() + static_cast<std::ptrdiff_t>(client.bytes_read()));
      break;
    case canopen::SdoStatus::kTimedOut:
      result.status = SdoResult::Status::kTimedOut;
      result.abort_code = canopen::abort_code::kTimeout;
      break;
    default:
      result.status = SdoResult::Status::kAborted;
      result.abort_code = client.abort_code();
      break;
  }
  return result;
}

SdoResult SdoSession::read(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub) {
  std::array<std::uint8_t, kMaxUploadBytes> buffer{};
  return run(
      node_id,
      [&](canopen::SdoClient& c) {
        return c.start_read(index, sub, buffer, link_.now_ns(), link_);
      },
      buffer);
}

SdoResult SdoSession::write(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub,
                            std::span<const std::uint8_t> data) {
  return run(
      node_id,
      [&](canopen::SdoClient& c) { return c.start_write(index, sub, data, link_.now_ns(), link_); },
      {});
}

SdoResult SdoSession::write_u32(std::uint8_t node_id, std::uint16_t index, std::uint8_t sub,
                                std::uint32_t value, std::size_t size) {
  return run(node_id,
             [&](canopen::SdoClient& c) {
               return c.start_write_u32(index, sub, value, size, link_.now_ns(), link_);
             },
             {});
}

}  // namespace planter::cantool
