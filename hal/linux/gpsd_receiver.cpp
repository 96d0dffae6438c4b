#include "hal/linux/gpsd_receiver.h"

#include <gps.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <string>

namespace planter::hal::linux_backend {

namespace {
double or_zero(double v) { return std::isfinite(v) ? v : 0.0; }
}  // namespace

double fix_time_s(const gps_data_t& data) {
  return static_cast<double>(data.fix.time.tv_sec) +
         1e-9 * static_cast<double>(data.fix.time.tv_nsec);
}

GnssFix fix_from_gpsd(const gps_data_t& data, std::int64_t arrival_ns, const GnssFix& previous,
                      double previous_time_s, std::int64_t latency_ns) {
  GnssFix f;
  f.sequence = previous.sequence + 1;
  const gps_fix_t& g = data.fix;
  const int mode = g.mode;
  f.mode = mode == MODE_3D       ? GnssMode::k3D
           : mode == MODE_2D     ? GnssMode::k2D
           : mode == MODE_NO_FIX ? GnssMode::kNoFix
                                 : GnssMode::kUnknown;
  f.satellites = data.satellites_used;
  f.hdop = or_zero(data.dop.hdop);
  // Unknown speed or track stays NaN: the fusion refuses it rather than taking 0 m/s.
  f.speed_mps = g.speed;
  f.track_deg = g.track;
  // gpsd's eps: "estimated speed error", certainty unstated; taken as 1 SD.
  f.speed_err_mps = or_zero(g.eps);
  f.lat_deg = or_zero(g.latitude);
  f.lon_deg = or_zero(g.longitude);
  f.valid_ns = arrival_ns - latency_ns;
  f.receiver_time_s = or_zero(fix_time_s(data));
  // A receiver (or a log) whose time stands still or runs back: the fix keeps the last one's
  // date, and the fusion takes it as no new fix.
  if (previous.sequence != 0 && fix_time_s(data) <= previous_time_s) f.valid_ns = previous.valid_ns;
  return f;
}

GpsdReceiver::GpsdReceiver(GpsdOptions options, std::function<std::int64_t()> now_ns)
    : options_(std::move(options)), now_ns_(std::move(now_ns)), thread_([this] { run(); }) {}

GpsdReceiver::~GpsdReceiver() {
  stop_ = true;
  if (thread_.joinable()) thread_.join();
}

void GpsdReceiver::watch(gps_data_t& data, GnssFix& last, double& last_time_s) {
  while (!stop_) {
    // gps_waiting is false both on a timeout and on an error, and says which only through
    // errno: clear it first, or a value left by the connect (EINPROGRESS) reads as an error and
    // a 1 Hz receiver's quiet 200 ms would drop the connection.
    errno = 0;
    if (!gps_waiting(&data, 200'000)) {
      if (errno != 0 && errno != EINTR && errno != EAGAIN) return;
      continue;
    }
    errno = 0;
    if (gps_read(&data, nullptr, 0) < 0) return;                             // gpsd went away
    if ((data.set & MODE_SET) == 0 || (data.set & TIME_SET) == 0) continue;  // not a TPV
    ++reports_;
    const GnssFix f = fix_from_gpsd(data, now_ns_(), last, last_time_s, options_.latency_ns);
    last_time_s = std::max(last_time_s, fix_time_s(data));
    last = f;
    box_.put(f);
  }
}

void GpsdReceiver::run() {
  const std::string port = std::to_string(options_.port);
  // Kept across connections: a fix's sequence is never reused, and a receiver whose time runs
  // back after gpsd restarts is still a receiver whose time runs back.
  GnssFix last;
  double last_time_s = -1.0;
  while (!stop_) {
    gps_data_t data{};
    if (gps_open(options_.host.c_str(), port.c_str(), &data) == 0) {
      if (gps_stream(&data, WATCH_ENABLE | WATCH_JSON, nullptr) == 0) {
        connected_ = true;
        ++connections_;
        watch(data, last, last_time_s);
        connected_ = false;
      }
      gps_stream(&data, WATCH_DISABLE, nullptr);
      gps_close(&data);
    }
    for (int i = 0; i < 10 && !stop_; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
}

}  // namespace planter::hal::linux_backend
