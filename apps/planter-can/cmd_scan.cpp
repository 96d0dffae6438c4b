#include "apps/planter-can/cmd_scan.h"

#include <array>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <ostream>

#include "apps/planter-can/object_names.h"
#include "apps/planter-can/sdo_session.h"
#include "firmware/canopen/cob_id.h"
#include "firmware/canopen/sdo_client.h"

namespace planter::cantool {

ScanResult scan_bus(ToolContext& ctx, const ScanOptions& opt) {
  ScanResult r;
  ToolLink& link = ctx.link;
  Progress progress(ctx.err, ctx.progress);
  const std::int64_t t0 = link.now_ns();
  r.watch.start(t0);
  hal::CanFrame f;
  // 1. Passive: who speaks on its own.
  while (link.receive_until(f, t0 + opt.listen_ns)) r.watch.on_frame(f, link.now_ns());

  // 2. Active: every ID at once, paced by the link, answers collected as they come.
  std::array<std::unique_ptr<canopen::SdoClient>, 128> clients{};
  std::array<std::array<std::uint8_t, 8>, 128> buffers{};
  // Every frame is watched; an SDO answer goes to the probe of its node.
  auto take = [&](const hal::CanFrame& frame) {
    r.watch.on_frame(frame, link.now_ns());
    const std::uint16_t cob = frame.cob_id();
    if (frame.is_standard_data() && cob > canopen::kSdoResponseBase && cob < 0x600 &&
        clients[cob & 0x7F])
      clients[cob & 0x7F]->on_frame(frame, link.now_ns(), link);
  };
  if (opt.probe) {
    for (int id = opt.first_id; id <= opt.last_id; ++id) {
      auto& c = clients[static_cast<std::size_t>(id)];
      c = std::make_unique<canopen::SdoClient>(static_cast<std::uint8_t>(id), ctx.sdo_timeout_ns);
      c->start_read(0x1000, 0, buffers[static_cast<std::size_t>(id)], link.now_ns(), link);
      ++r.probes_sent;
      // Take answers that already arrived so the receive queue never fills while sending.
      while (link.receive(f)) take(f);
      progress.update("probing node " + std::to_string(id) + "/127");
    }
    for (;;) {
      bool busy = false;
      const std::int64_t now = link.now_ns();
      for (auto& c : clients) {
        if (!c) continue;
        c->poll(now, link);
        busy = busy || c->status() == canopen::SdoStatus::kBusy;
      }
      if (!busy) break;
      if (link.receive_until(f, now + 5'000'000)) take(f);
    }
  }
  // 3. Identity of everything that answered or spoke.
  SdoSession sdo(link, ctx.sdo_timeout_ns);
  sdo.set_observer([&r](const hal::CanFrame& fr, std::int64_t t) { r.watch.on_frame(fr, t); });
  for (int id = 1; id <= 127; ++id) {
    const auto& c = clients[static_cast<std::size_t>(id)];
    const bool answered = c && c->status() == canopen::SdoStatus::kDone;
    if (!answered && !r.watch.node(static_cast<std::uint8_t>(id)).seen) continue;
    ScannedNode n;
    n.id = static_cast<std::uint8_t>(id);
    n.answered_sdo = answered;
    n.role = node_role_of(ctx, n.id);
    if (answered) {
      n.device_type = static_cast<std::uint32_t>(c->value());
      progress.update("reading identity of node " + std::to_string(id));
      auto u32 = [&](std::uint16_t index, std::uint8_t sub) -> std::uint32_t {
        const SdoResult res = sdo.read(n.id, index, sub);
        return res.ok() ? static_cast<std::uint32_t>(res.value()) : 0;
      };
      n.vendor = u32(0x1018, 1);
      n.product = u32(0x1018, 2);
      n.revision = u32(0x1018, 3);
      n.serial = u32(0x1018, 4);
      const SdoResult name = sdo.read(n.id, 0x1008, 0);
      if (name.ok()) n.device_name.assign(name.data.begin(), name.data.end());
    }
    r.nodes.push_back(n);
  }
  // Heartbeat states as last heard (identity reads took some more listening time).
  for (auto& n : r.nodes) n.state = r.watch.node(n.id).state;
  progress.done();
  r.duration_ns = link.now_ns() - t0;
  return r;
}

int run_scan(ToolContext& ctx, const ScanOptions& opt) {
  const ScanResult r = scan_bus(ctx, opt);
  if (ctx.json) {
    nlohmann::json j;
    j["interface"] = ctx.link.name();
    j["duration_s"] = static_cast<double>(r.duration_ns) * 1e-9;
    j["probes"] = r.probes_sent;
    j["nodes"] = nlohmann::json::array();
    for (const auto& n : r.nodes) {
      j["nodes"].push_back({{"id", n.id},
                            {"role", n.role},
                            {"answered_sdo", n.answered_sdo},
                            {"device_type", n.device_type},
                            {"profile", n.device_type & 0xFFFF},
                            {"vendor_id", n.vendor},
                            {"product_code", n.product},
                            {"revision", n.revision},
                            {"serial", n.serial},
                            {"name", n.device_name},
                            {"state", nmt_state_name(n.state)}});
    }
    ctx.out << j.dump(2) << "\n";
    return kExitOk;
  }
  char line[256];
  std::snprintf(line, sizeof line, "%-4s %-16s %-26s %-10s %-10s %-8s %-10s %-16s %s\n", "node",
                "role", "profile", "vendor", "product", "rev", "serial", "state", "name");
  ctx.out << line;
  for (const auto& n : r.nodes) {
    if (n.answered_sdo) {
      std::snprintf(line, sizeof line, "%-4u %-16s %-26s 0x%08X 0x%08X %-8u 0x%08X %-16s %s\n",
                    n.id, n.role.empty() ? "-" : n.role.c_str(), device_profile_text(n.device_type),
                    n.vendor, n.product, n.revision, n.serial, nmt_state_name(n.state),
                    n.device_name.c_str());
    } else {
      std::snprintf(line, sizeof line, "%-4u %-16s %-26s %-10s %-10s %-8s %-10s %-16s %s\n", n.id,
                    n.role.empty() ? "-" : n.role.c_str(), "(no SDO answer)", "-", "-", "-", "-",
                    nmt_state_name(n.state), "");
    }
    ctx.out << line;
  }
  std::snprintf(line, sizeof line, "%zu node(s) on %s; %u IDs probed in %.3f s\n", r.nodes.size(),
                ctx.link.name().c_str(), r.probes_sent, static_cast<double>(r.duration_ns) * 1e-9);
  ctx.out << line;
  return kExitOk;
}

}  // namespace planter::cantool
