#include "apps/planter-can/cmd_check.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <nlohmann/json.hpp>
#include <ostream>

#include "apps/planter-can/bus_watch.h"
#include "apps/planter-can/cmd_scan.h"
#include "apps/planter-can/object_names.h"
#include "apps/planter-can/operator_prompt.h"
#include "apps/planter-can/sdo_session.h"
#include "apps/planter-can/text_format.h"
#include "config/commissioning.h"
#include "firmware/canopen/cob_id.h"
#include "firmware/sensing/quadrature_decoder.h"

namespace planter::cantool {
namespace {

struct Item {
  std::string name;
  bool pass = false;
  std::string detail;
};
using Items = std::vector<Item>;

std::string node_name(const NodeConfig& n) {
  return format_text("%s (node %u)", node_role_name(n.role), n.node_id);
}

// 1. Presence, identity and profile, error register: each node read over SDO.
void check_identities(const ToolContext& ctx, const ControllerConfig& cfg, SdoSession& sdo,
                      Items& items) {
  for (const auto& n : cfg.nodes) {
    const std::string who = node_name(n);
    const SdoResult type = sdo.read(n.node_id, 0x1000, 0);
    if (!type.ok()) {
      items.push_back({who + " present", false, type.error_text(n.node_id, ctx.sdo_timeout_ns)});
      continue;
    }
    const auto profile = static_cast<std::uint16_t>(type.value() & 0xFFFF);
    items.push_back({who + " profile", profile == n.profile,
                     format_text("CiA %u, board expects %u", profile, n.profile)});
    const SdoResult vendor = sdo.read(n.node_id, 0x1018, 1);
    const SdoResult product = sdo.read(n.node_id, 0x1018, 2);
    const bool id_ok = vendor.ok() && product.ok() &&
                       (n.vendor_id == 0 || vendor.value() == n.vendor_id) &&
                       (n.product_code == 0 || product.value() == n.product_code);
    items.push_back(
        {who + " identity", id_ok,
         format_text("vendor 0x%08X product 0x%08X (board 0x%08X 0x%08X)",
                     static_cast<unsigned>(vendor.value()), static_cast<unsigned>(product.value()),
                     n.vendor_id, n.product_code)});
    const SdoResult er = sdo.read(n.node_id, 0x1001, 0);
    items.push_back({who + " error register", er.ok() && er.value() == 0,
                     er.ok() ? format_text("0x%02X", static_cast<unsigned>(er.value()))
                             : er.error_text(n.node_id, ctx.sdo_timeout_ns)});
  }
}

// 2a. Each node's heartbeats over the listening window [.., t1_ns], and its EMCYs.
void check_heartbeats(const ControllerConfig& cfg, const BusWatch& watch, std::int64_t listen_ns,
                      std::int64_t t1_ns, Items& items) {
  const double hb_limit_ms = cfg.can.heartbeat_producer_ms * cfg.can.heartbeat_consumer_factor;
  for (const auto& n : cfg.nodes) {
    const NodeSeen& s = watch.node(n.node_id);
    const std::string who = node_name(n);
    const double gap_ms = static_cast<double>(s.max_heartbeat_gap_ns) * 1e-6;
    const double since_ms = static_cast<double>(t1_ns - s.last_heartbeat_ns) * 1e-6;
    const bool ok = s.heartbeats >= 2 && gap_ms <= hb_limit_ms && since_ms <= hb_limit_ms;
    items.push_back(
        {who + " heartbeat", ok,
         s.heartbeats == 0
             ? format_text("none in %.1f s (is 0x1017 set? run configure)",
                           static_cast<double>(listen_ns) * 1e-9)
             : format_text("%u beats, longest gap %.0f ms (limit %.0f ms), state %s", s.heartbeats,
                           gap_ms, hb_limit_ms, nmt_state_name(s.state))});
    if (s.emcy_count > 0) {
      items.push_back({who + " EMCY", false,
                       format_text("%u EMCY, last 0x%04X %s", s.emcy_count, s.last_emcy_code,
                                   emcy_code_text(s.last_emcy_code))});
    }
  }
}

// 2b. The SYNC's rate against the board's, and each mapped TPDO at one per SYNC.
void check_sync_and_pdos(const ControllerConfig& cfg, const BusWatch& watch, Items& items) {
  const auto sync_it = watch.cobs().find(canopen::kSyncCobId);
  const double sync_hz = sync_it == watch.cobs().end() ? 0.0 : sync_it->second.rate_hz();
  const double sync_expected_hz = 1e9 / static_cast<double>(cfg.can.sync_period_ns);
  items.push_back({"SYNC rate", std::fabs(sync_hz - sync_expected_hz) <= 0.05 * sync_expected_hz,
                   sync_hz == 0.0
                       ? std::string("no SYNC on the bus (is planterd running?)")
                       : format_text("%.1f Hz, board %.1f Hz", sync_hz, sync_expected_hz)});
  for (const auto& n : cfg.nodes) {
    for (std::size_t k = 0; k < 4; ++k) {
      if (n.tpdo[k].count == 0) continue;
      const auto cob = static_cast<std::uint16_t>(canopen::kTpdoBase[k] + n.node_id);
      const auto it = watch.cobs().find(cob);
      const double hz = it == watch.cobs().end() ? 0.0 : it->second.rate_hz();
      // Transmission type 1: one TPDO per SYNC.
      const bool ok = sync_hz > 0.0 && std::fabs(hz - sync_hz) <= 0.05 * sync_hz;
      items.push_back({format_text("%s TPDO%zu rate", node_role_name(n.role), k + 1), ok,
                       format_text("%.1f Hz on 0x%03X, expected %.1f Hz (every SYNC)", hz, cob,
                                   sync_hz > 0 ? sync_hz : sync_expected_hz)});
    }
  }
}

// 2c. Bus load, error frames and frames lost since the check began.
void check_bus_counters(const ToolContext& ctx, const CheckOptions& opt,
                        const ControllerConfig& cfg, const BusWatch& watch,
                        const hal::CanBusCounters& before, std::int64_t t1_ns, Items& items) {
  const double load = watch.bus_load_pct(cfg.can.bitrate_bps, t1_ns);
  items.push_back({"bus load", load <= opt.max_bus_load_pct,
                   format_text("%.1f %% at %u bit/s (limit %.0f %%)", load, cfg.can.bitrate_bps,
                               opt.max_bus_load_pct)});
  const auto counters = ctx.link.counters();
  const auto new_errors = counters.error_frames - before.error_frames + watch.error_frames();
  items.push_back({"error frames", new_errors == 0 && !counters.bus_off,
                   format_text("%llu error frames%s", static_cast<unsigned long long>(new_errors),
                               counters.bus_off ? ", bus-off" : "")});
  items.push_back(
      {"lost frames",
       counters.rx_overflow == before.rx_overflow && counters.tx_dropped == before.tx_dropped,
       format_text("%u receive overflows, %u refused sends",
                   counters.rx_overflow - before.rx_overflow,
                   counters.tx_dropped - before.tx_dropped)});
}

// 3. Encoder direction: a push forward must count up.
Item check_encoder(ToolContext& ctx, const CheckOptions& opt, std::istream& in) {
  const ControllerConfig& cfg = ctx.board->controller;
  hal::GpioEdgeSource* edges = ctx.link.encoder();
  if (edges == nullptr)
    return {"encoder direction", false,
            "no access to the encoder lines (run on the board, or --skip-encoder)"};
  QuadratureDecoder decoder(cfg.encoder.glitch_filter_ns);
  hal::GpioEdge e;
  while (edges->next_edge(e)) {
  }
  OperatorPrompt person(ctx.link, in, ctx.err, opt.ready_after_s);
  if (!person.ask("push the machine forward a little (half a metre is plenty)",
                  OperatorAction::kPushMachine, 0.5))
    return {"encoder direction", false, "nobody pushed the machine"};
  const std::int64_t t2 = ctx.link.now_ns();
  hal::CanFrame f;
  while (ctx.link.now_ns() - t2 < 5'000'000'000 && std::llabs(decoder.count()) < 200) {
    ctx.link.receive_until(f, ctx.link.now_ns() + 10'000'000);
    while (edges->next_edge(e)) decoder.on_edge(e);
  }
  const auto c = static_cast<long long>(decoder.count());
  if (c >= 200) return {"encoder direction", true, format_text("%lld counts forward", c)};
  return {"encoder direction", false,
          c <= -200 ? format_text("%lld counts: A and B are swapped (swap encoder_a_line and "
                                  "encoder_b_line)",
                                  c)
                    : format_text("%lld counts in 5 s: the wheel did not turn", c)};
}

// The items as JSON or as lines with the count, and whether the stamp was written.
void print_items(const ToolContext& ctx, const CheckOptions& opt, const Items& items, int failed,
                 bool stamped) {
  if (ctx.json) {
    nlohmann::json j{{"board", ctx.board->name},
                     {"interface", ctx.link.name()},
                     {"passed", failed == 0},
                     {"failed_items", failed}};
    for (const auto& i : items)
      j["items"].push_back({{"item", i.name}, {"pass", i.pass}, {"detail", i.detail}});
    if (!opt.mark_commissioned.empty())
      j["commissioned_stamp"] = stamped ? opt.mark_commissioned : "";
    ctx.out << j.dump(2) << "\n";
    return;
  }
  for (const auto& i : items) {
    char line[400];
    std::snprintf(line, sizeof line, "%-4s  %-36s %s\n", i.pass ? "pass" : "FAIL", i.name.c_str(),
                  i.detail.c_str());
    ctx.out << line;
  }
  ctx.out << (failed == 0 ? "all " + std::to_string(items.size()) + " items passed\n"
                          : std::to_string(failed) + " of " + std::to_string(items.size()) +
                                " items failed\n");
  if (stamped)
    ctx.out << "commissioned: " << opt.mark_commissioned
            << " written (planterd may start the drives)\n";
  if (failed > 0 && !opt.mark_commissioned.empty())
    ctx.out << "not commissioned: " << opt.mark_commissioned << " left as it was\n";
}

}  // namespace

int run_check(ToolContext& ctx, const CheckOptions& opt, std::istream& in) {
  if (ctx.board == nullptr) {
    ctx.err << "planter-can: check needs --board (it checks the bus against it)\n";
    return kExitBadInput;
  }
  const ControllerConfig& cfg = ctx.board->controller;
  Items items;
  BusWatch watch;
  SdoSession sdo(ctx.link, ctx.sdo_timeout_ns);
  sdo.set_observer([&watch](const hal::CanFrame& f, std::int64_t t) { watch.on_frame(f, t); });
  const auto counters_before = ctx.link.counters();
  check_identities(ctx, cfg, sdo, items);

  // 2. Listen: heartbeats, PDO rates, SYNC, EMCY, bus load.
  Progress progress(ctx.err, ctx.progress);
  const std::int64_t t0 = ctx.link.now_ns();
  watch.start(t0);
  hal::CanFrame f;
  while (ctx.link.now_ns() - t0 < opt.listen_ns) {
    if (ctx.link.receive_until(f, t0 + opt.listen_ns)) watch.on_frame(f, ctx.link.now_ns());
    progress.update("listening to the bus...");
  }
  progress.done();
  const std::int64_t t1 = ctx.link.now_ns();
  check_heartbeats(cfg, watch, opt.listen_ns, t1, items);
  check_sync_and_pdos(cfg, watch, items);
  check_bus_counters(ctx, opt, cfg, watch, counters_before, t1, items);
  if (opt.encoder) items.push_back(check_encoder(ctx, opt, in));

  int failed = 0;
  for (const auto& i : items) failed += i.pass ? 0 : 1;
  std::string stamp_error;
  const bool stamped =
      failed == 0 && !opt.mark_commissioned.empty() &&
      config::write_commissioning_stamp(opt.mark_commissioned, ctx.board->file, ctx.board->name,
                                        static_cast<std::int64_t>(std::time(nullptr)), stamp_error);
  print_items(ctx, opt, items, failed, stamped);
  if (!stamp_error.empty()) {
    ctx.err << "planter-can: check: " << stamp_error << "\n";
    return kExitFailed;
  }
  return failed == 0 ? kExitOk : kExitFailed;
}

}  // namespace planter::cantool
