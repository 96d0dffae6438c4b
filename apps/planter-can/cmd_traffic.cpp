#include "apps/planter-can/cmd_traffic.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <ostream>
#include <sstream>
#include <vector>

#include "apps/planter-can/bus_watch.h"
#include "apps/planter-can/candump_log.h"
#include "apps/planter-can/frame_decoder.h"
#include "config/config_error.h"
#include "config/durable_file.h"
#include "config/input_file.h"
#include "firmware/canopen/cob_id.h"
#include "firmware/io/signal_table.h"

namespace planter::cantool {
namespace {

bool stopped(const TrafficOptions& o) { return o.stop != nullptr && o.stop->load(); }

// On `sim` nobody can press Ctrl-C in simulated time, and time runs as fast as the CPU: an
// open-ended monitor or record would never end. Refused with a message (exit 2).
bool open_ended_on_sim(ToolContext& ctx, const TrafficOptions& opt, const char* command) {
  if (opt.duration_s > 0 || ctx.link.fixture() == nullptr) return false;
  ctx.err << "planter-can: " << command
          << ": on --iface sim time is simulated and never interrupted: give --duration S "
             "(above 0)\n";
  return true;
}

// Deadline from a duration; "forever" (until stopped) when 0.
std::int64_t end_of(ToolLink& link, double duration_s) {
  return duration_s > 0 ? link.now_ns() + static_cast<std::int64_t>(duration_s * 1e9)
                        : INT64_MAX / 2;
}

void print_summary(ToolContext& ctx, const BusWatch& watch, const FrameDecoder& decoder,
                   std::int64_t now_ns) {
  const std::uint32_t bitrate = ctx.board ? ctx.board->controller.can.bitrate_bps : 500000;
  const auto c = ctx.link.counters();
  if (ctx.json) {
    nlohmann::json j{{"summary", true},
                     {"frames", watch.frames()},
                     {"bus_load_pct", watch.bus_load_pct(bitrate, now_ns)},
                     {"error_frames", watch.error_frames() + c.error_frames},
                     {"rx_overflow", c.rx_overflow},
                     {"bus_off", c.bus_off}};
    for (const auto& [cob, s] : watch.cobs()) {
      const DecodedFrame d = decoder.decode(s.last);
      j["cobs"].push_back({{"cob_id", cob},
                           {"service", service_name(d.service)},
                           {"node", d.node},
                           {"count", s.count},
                           {"rate_hz", s.rate_hz()},
                           {"last", d.text}});
    }
    ctx.out << j.dump() << "\n";
    return;
  }
  char line[400];
  std::snprintf(line, sizeof line, "%-5s %-7s %-18s %8s %9s  %s\n", "COB", "service", "node",
                "frames", "rate Hz", "last value");
  ctx.out << line;
  for (const auto& [cob, s] : watch.cobs()) {
    const DecodedFrame d = decoder.decode(s.last);
    const std::string node = d.node == 0 ? "-"
                             : d.node_name.empty()
                                 ? std::to_string(d.node)
                                 : d.node_name + " (" + std::to_string(d.node) + ")";
    std::snprintf(line, sizeof line, "0x%03X %-7s %-18s %8llu %9.1f  %s\n", cob,
                  service_name(d.service), node.c_str(), static_cast<unsigned long long>(s.count),
                  s.rate_hz(), d.text.c_str());
    ctx.out << line;
  }
  std::snprintf(line, sizeof line,
                "%llu frames, bus load %.1f %% at %u bit/s, %llu error frames, %u rx overflows%s\n",
                static_cast<unsigned long long>(watch.frames()),
                watch.bus_load_pct(bitrate, now_ns), bitrate,
                static_cast<unsigned long long>(watch.error_frames() + c.error_frames),
                c.rx_overflow, c.bus_off ? ", BUS-OFF" : "");
  ctx.out << line;
}

}  // namespace

int run_monitor(ToolContext& ctx, const TrafficOptions& opt) {
  if (open_ended_on_sim(ctx, opt, "monitor")) return kExitBadInput;
  const FrameDecoder decoder(ctx.board ? &ctx.board->controller : nullptr);
  BusWatch watch;
  const std::int64_t t0 = ctx.link.now_ns();
  watch.start(t0);
  const std::int64_t end = end_of(ctx.link, opt.duration_s);
  std::int64_t next_summary = opt.summary_every_s > 0
                                  ? t0 + static_cast<std::int64_t>(opt.summary_every_s * 1e9)
                                  : INT64_MAX;
  hal::CanFrame f;
  while (!stopped(opt) && ctx.link.now_ns() < end) {
    const std::int64_t wake = std::min({end, next_summary, ctx.link.now_ns() + 100'000'000});
    if (ctx.link.receive_until(f, wake)) {
      const std::int64_t now = ctx.link.now_ns();
      watch.on_frame(f, now);
      if (!opt.summary_only) {
        const DecodedFrame d = decoder.decode(f);
        const double t = static_cast<double>(now - t0) * 1e-9;
        if (ctx.json) {
          nlohmann::json j{
              {"t", t},         {"cob_id", f.cob_id()}, {"service", service_name(d.service)},
              {"node", d.node}, {"text", d.text},       {"malformed", d.malformed}};
          if (!d.node_name.empty()) j["role"] = d.node_name;
          for (const auto& v : d.values)
            j["values"].push_back(
                {{"name", v.name}, {"value", v.value}, {"unit", v.unit}, {"raw", v.raw}});
          ctx.out << j.dump() << "\n";
        } else {
          char line[512];
          const std::string node = d.node == 0 ? ""
                                   : d.node_name.empty()
                                       ? std::to_string(d.node)
                                       : d.node_name + "(" + std::to_string(d.node) + ")";
          std::snprintf(line, sizeof line, "%10.4f  %-20s %-7s %s%s%s\n", t, node.c_str(),
                        service_name(d.service), d.text.c_str(), opt.raw ? "   | " : "",
                        opt.raw ? raw_frame_text(f).c_str() : "");
          ctx.out << line;
        }
      }
    }
    if (ctx.link.now_ns() >= next_summary) {
      print_summary(ctx, watch, decoder, ctx.link.now_ns());
      next_summary += static_cast<std::int64_t>(opt.summary_every_s * 1e9);
    }
  }
  print_summary(ctx, watch, decoder, ctx.link.now_ns());
  return kExitOk;
}

int run_record(ToolContext& ctx, const std::string& path, const TrafficOptions& opt) {
  if (open_ended_on_sim(ctx, opt, "record")) return kExitBadInput;
  if (const std::string refusal = config::new_log_refusal(path); !refusal.empty()) {
    ctx.err << "planter-can: record: " << path << ": " << refusal << "\n";
    return kExitBadInput;
  }
  std::ofstream out(path, std::ios::app);  // new: appended, never truncated
  if (!out) {
    ctx.err << "planter-can: record: " << path << ": cannot be written\n";
    return kExitBadInput;
  }
  LogWriter writer(out, ctx.link.name());
  FrameTap* outer = ctx.link.tap();  // a session log (--record) keeps running alongside
  TapPair both(writer, outer);
  ctx.link.set_tap(&both);
  const std::int64_t end = end_of(ctx.link, opt.duration_s);
  hal::CanFrame f;
  std::int64_t next_flush = ctx.link.now_ns() + 1'000'000'000;
  Progress progress(ctx.err, ctx.progress);
  while (!stopped(opt) && ctx.link.now_ns() < end) {
    ctx.link.receive_until(f, std::min(end, ctx.link.now_ns() + 100'000'000));
    if (ctx.link.now_ns() >= next_flush) {
      out.flush();  // a killed recorder loses at most a second
      next_flush += 1'000'000'000;
      progress.update("recorded " + std::to_string(writer.frames()) + " frames");
    }
  }
  ctx.link.set_tap(outer);
  out.flush();
  out.close();  // a full disk shows at the last flush or the close: both are checked
  progress.done();
  if (!out) {
    ctx.err << "planter-can: record: " << path << ": cannot be written (disk full?)\n";
    return kExitFailed;
  }
  if (ctx.json) {
    ctx.out << nlohmann::json{{"file", path}, {"frames", writer.frames()}}.dump(2) << "\n";
  } else {
    ctx.out << writer.frames() << " frames recorded to " << path << "\n";
  }
  return kExitOk;
}

namespace {

bool read_log(const std::string& path, std::vector<LogRecord>& records, std::ostream& err) {
  try {
    config::require_regular_file(path);  // a FIFO would block, a directory reads as empty
  } catch (const config::ConfigError& e) {
    err << "planter-can: " << e.what() << "\n";
    return false;
  }
  std::ifstream in(path);
  if (!in) {
    err << "planter-can: " << path << ": cannot be read\n";
    return false;
  }
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    if (number == 1) config::strip_utf8_bom(line);  // else its first frame reads as a comment
    LogParse p = parse_log_line(line);
    if (p.kind == LogLineKind::kError && in.eof()) {
      // The last line has no newline and does not parse: a recorder stopped mid-line (a kill
      // or a power cut). The frames before it are whole; only that line is lost.
      err << "planter-can: " << path << ":" << number
          << ": the last line is cut (the recording stopped mid-line): ignored\n";
      break;
    }
    if (p.kind == LogLineKind::kError) {
      err << "planter-can: " << path << ":" << number << ": " << p.error << "\n";
      return false;
    }
    if (p.kind == LogLineKind::kFrame) {
      // Kernel stamps of frames from different senders may step back a little (candump
      // shows the same); a step back of more than a second is a spliced or damaged log.
      if (!records.empty() && p.record.time_ns < records.back().time_ns - 1'000'000'000) {
        err << "planter-can: " << path << ":" << number << ": time goes back by more than 1 s\n";
        return false;
      }
      records.push_back(std::move(p.record));
    }
  }
  if (in.bad()) {
    err << "planter-can: " << path << ":" << number << ": cannot be read\n";
    return false;
  }
  if (records.empty()) {
    err << "planter-can: " << path << ": no frame lines (candump -L: '(time) iface id#data'); "
        << number << " line(s) read\n";
    return false;
  }
  return true;
}

}  // namespace

int run_replay(ToolContext& ctx, const std::string& path, const TrafficOptions& opt) {
  std::vector<LogRecord> records;
  if (!read_log(path, records, ctx.err)) return kExitBadInput;
  if (!(opt.speed > 0.0)) {
    ctx.err << "planter-can: replay: --speed must be above 0\n";
    return kExitBadInput;
  }
  const std::int64_t t0 = ctx.link.now_ns();
  std::uint64_t sent = 0, refused = 0, shortened = 0;
  hal::CanFrame f;
  Progress progress(ctx.err, ctx.progress);
  // Log time with every silence longer than max_gap_s cut to max_gap_s (a log spliced from
  // two sessions, or a clock that jumped, would otherwise be replayed for hours).
  const auto max_gap_ns = static_cast<std::int64_t>(opt.max_gap_s * 1e9);
  std::int64_t log_elapsed_ns = 0, previous_ns = records.front().time_ns;
  for (const auto& r : records) {
    if (stopped(opt)) break;
    // In file order; a frame stamped a little before its predecessor goes right after it.
    const std::int64_t gap = std::max<std::int64_t>(0, r.time_ns - previous_ns);
    if (gap > max_gap_ns) ++shortened;
    log_elapsed_ns += std::min(gap, max_gap_ns);
    previous_ns = std::max(previous_ns, r.time_ns);
    const auto at = t0 + static_cast<std::int64_t>(static_cast<double>(log_elapsed_ns) / opt.speed);
    while (ctx.link.now_ns() < at) ctx.link.receive_until(f, at);  // keep the rx queue drained
    if (r.frame.id & hal::CanFrame::kErrorFlag) continue;          // error frames are not sendable
    if (ctx.link.send(r.frame)) {
      ++sent;
    } else {
      ++refused;
    }
    progress.update("replayed " + std::to_string(sent) + "/" + std::to_string(records.size()));
  }
  progress.done();
  if (ctx.json) {
    ctx.out << nlohmann::json{{"file", path},
                              {"frames", records.size()},
                              {"sent", sent},
                              {"refused", refused},
                              {"gaps_shortened", shortened}}
                   .dump(2)
            << "\n";
  } else {
    ctx.out << sent << " of " << records.size() << " frames replayed from " << path
            << (refused ? " (" + std::to_string(refused) + " refused by the bus)" : "") << "\n";
    if (shortened > 0) {
      ctx.out << shortened << " silence(s) longer than " << opt.max_gap_s << " s shortened to "
              << opt.max_gap_s << " s\n";
    }
  }
  return refused == 0 ? kExitOk : kExitFailed;
}

namespace {

// The recording's columns that travel on the bus (signal table), in recording order, and the
// values a log's PDOs carry for them under the board's maps and scalings.
class BusColumns {
 public:
  explicit BusColumns(const config::BoardConfig& board) : decoder_(&board.controller) {
    for (const SignalDecl& s : kSignals) {
      if (s.recorded && s.on_bus()) columns_.push_back(&s);
    }
  }
  [[nodiscard]] std::size_t size() const { return columns_.size(); }
  [[nodiscard]] const SignalDecl& column(std::size_t i) const { return *columns_[i]; }
  [[nodiscard]] DecodedFrame decode(const hal::CanFrame& f) const { return decoder_.decode(f); }
  // take(column, value) for each value of a well-formed PDO that a column records.
  template <class Take>
  void for_each_value(const DecodedFrame& d, Take&& take) const {
    if ((d.service != Service::kTpdo && d.service != Service::kRpdo) || d.malformed) return;
    const NodeConfig* node = decoder_.node_config(d.node);
    if (node == nullptr) return;
    for (const auto& v : d.values) {
      for (std::size_t i = 0; i < columns_.size(); ++i) {
        const SignalDecl& c = *columns_[i];
        const bool rpdo = c.source == SignalSource::kController;
        if (c.role == node->role && c.index == v.index && c.sub == v.sub &&
            rpdo == (d.service == Service::kRpdo))
          take(i, v.value);
      }
    }
  }

 private:
  std::vector<const SignalDecl*> columns_;
  FrameDecoder decoder_;
};

// Which columns the log carries. Columns whose objects never appear in it are left out
// (docs/recording-format.md: columns may be absent). PDOs shorter (or longer) than the board
// maps them carry no value: counted and named, so a log of them does not pass as a recording
// of fewer columns (issue 53, item 6); false when no measured value could be decoded.
bool columns_present(const BusColumns& bus, const std::vector<LogRecord>& records,
                     const std::string& log_path, std::ostream& err, std::vector<bool>& present) {
  present.assign(bus.size(), false);
  std::size_t bad_pdos = 0;
  std::string first_bad;
  for (const auto& r : records) {
    if (!r.frame.is_standard_data()) continue;
    const DecodedFrame d = bus.decode(r.frame);
    bus.for_each_value(d, [&](std::size_t i, double) { present[i] = true; });
    if ((d.service == Service::kTpdo || d.service == Service::kRpdo) && d.malformed) {
      if (bad_pdos++ == 0) first_bad = (d.node_name.empty() ? "" : d.node_name + " ") + d.text;
    }
  }
  if (bad_pdos == 0) return true;
  bool any_measured = false;
  for (std::size_t i = 0; i < bus.size(); ++i)
    any_measured = any_measured || (present[i] && bus.column(i).source == SignalSource::kNode);
  err << "planter-can: decode: " << log_path << ": " << bad_pdos
      << " PDOs do not match the board's maps (the first: " << first_bad
      << "); their values are not in the CSV\n";
  if (!any_measured) {
    err << "planter-can: decode: no PDO of the log could be decoded with this board's maps: is "
           "it this machine's log, and this board?\n";
  }
  return any_measured;
}

struct DecodedRows {
  std::size_t rows = 0;
  std::size_t syncs_same_time = 0;  // SYNCs at the time of the row before: no row of their own
};

// One row per SYNC: the values the controller had for that cycle. Rows start once every
// present column has a value, so no cell is empty; the time strictly increases.
DecodedRows write_rows(const BusColumns& bus, const std::vector<LogRecord>& records,
                       const std::vector<bool>& present, std::ostream& csv) {
  std::vector<double> values(bus.size(), 0.0);
  std::vector<bool> seen(bus.size(), false);
  const std::int64_t t0 = records.front().time_ns;
  DecodedRows n;
  std::int64_t last_row_ns = 0;
  for (const auto& r : records) {
    if (!r.frame.is_standard_data()) continue;
    if (r.frame.cob_id() != canopen::kSyncCobId) {
      bus.for_each_value(bus.decode(r.frame), [&](std::size_t i, double v) {
        values[i] = v;
        seen[i] = true;
      });
      continue;
    }
    if (n.rows > 0 && r.time_ns <= last_row_ns) {
      ++n.syncs_same_time;
      continue;
    }
    bool complete = true;
    for (std::size_t i = 0; i < bus.size(); ++i) complete = complete && (seen[i] || !present[i]);
    if (!complete) continue;
    char b[48];
    std::snprintf(b, sizeof b, "%.6f", static_cast<double>(r.time_ns - t0) * 1e-9);
    csv << b;
    for (std::size_t i = 0; i < bus.size(); ++i) {
      if (!present[i]) continue;
      std::snprintf(b, sizeof b, ",%.6g", values[i]);
      csv << b;
    }
    csv << "\n";
    ++n.rows;
    last_row_ns = r.time_ns;
  }
  return n;
}

}  // namespace

int run_decode(const config::BoardConfig* board, const std::string& log_path,
               const std::string& out_path, std::ostream& out, std::ostream& err) {
  if (board == nullptr) {
    err << "planter-can: decode needs --board (the PDO maps and scalings come from it)\n";
    return kExitBadInput;
  }
  std::vector<LogRecord> records;
  if (!read_log(log_path, records, err)) return kExitBadInput;
  std::size_t syncs = 0;
  for (const auto& r : records)
    syncs += r.frame.is_standard_data() && r.frame.cob_id() == canopen::kSyncCobId;
  if (syncs == 0) {
    err << "planter-can: decode: " << log_path << " has no SYNC frames to sample the signals on\n";
    return kExitFailed;
  }
  const BusColumns bus(*board);
  std::vector<bool> present;
  if (!columns_present(bus, records, log_path, err, present)) return kExitFailed;
  // Built in memory and written whole at the end (temporary + rename): a bad log leaves an
  // existing CSV as it was, and a full disk leaves no half file.
  std::ostringstream file;
  std::ostream& csv = out_path.empty() ? out : file;
  csv << "# source: " << log_path << "\n# board: " << board->name << "\nt";
  for (std::size_t i = 0; i < bus.size(); ++i) {
    if (present[i]) csv << "," << bus.column(i).column;
  }
  csv << "\n";
  const DecodedRows n = write_rows(bus, records, present, csv);
  // A log whose SYNCs share their times (a log without timestamps, or stamped by a clock that
  // stood) would collapse into a few rows: refused, not written short.
  if (n.syncs_same_time > 0 && n.syncs_same_time * 10 > syncs) {
    err << "planter-can: decode: " << log_path << ": " << n.syncs_same_time << " of " << syncs
        << " SYNC frames have the time of the one before: the log's timestamps do not advance "
           "(a candump -L log with its times is needed)\n";
    return kExitFailed;
  }
  if (!out_path.empty()) {
    if (std::string why; !config::write_file_atomic(out_path, file.str(), &why)) {
      err << "planter-can: decode: " << out_path << ": " << why << "\n";
      return kExitFailed;
    }
    out << n.rows << " rows (one per SYNC) from " << records.size() << " frames written to "
        << out_path << "\n";
  }
  return kExitOk;
}

}  // namespace planter::cantool
