#pragma once
// The simulated GNSS receiver's end of the controller's GnssSource: the plant's receiver
// model (sim/plant/gnss_receiver.h) puts each fix when the receiver would deliver it.
#include <vector>

#include "planter/hal/gnss.h"

namespace planter::hal::sim {

class SimGnss final : public GnssSource {
 public:
  void put(const GnssFix& fix) {
    box_.put(fix);
    log_.push_back(fix);
  }
  // Every fix delivered, in order (the run's NMEA log is written from it).
  [[nodiscard]] const std::vector<GnssFix>& log() const { return log_; }
  void set_connected(bool up) { connected_ = up; }
  bool latest(GnssFix& fix) override { return box_.get(fix); }
  [[nodiscard]] bool connected() const override { return connected_; }

 private:
  GnssMailbox box_;
  bool connected_ = true;
  std::vector<GnssFix> log_;
};

}  // namespace planter::hal::sim
