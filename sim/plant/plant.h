#pragma once
// The machine and the field around the simulated drives and sensors: reads what the CANopen
// devices were commanded, integrates the physics, writes back their measured values and
// produces the soil-wheel encoder edges.
#include <cstdint>
#include <random>

#include "firmware/controller/controller_config.h"
#include "hal/sim/sim_gpio.h"
#include "sim/devices/cia402_drive_device.h"
#include "sim/plant/drive_models.h"
#include "sim/plant/gnss_receiver.h"
#include "sim/plant/ground.h"
#include "sim/plant/plant_config.h"
#include "sim/plant/seedling_process.h"
#include "sim/plant/soil_wheel_encoder.h"

namespace planter::sim {

struct PlantDevices {
  Cia402DriveDevice& disc;
  Cia402DriveDevice& roller;
  Cia402DriveDevice& depth;
  Cia404ForceSensor& force;
  hal::sim::SimGnss* gnss = nullptr;  // the GNSS receiver, where the board has one
};

// Ground truth, for the recording and the summary (the controller never sees it).
struct PlantTruth {
  double x_m = 0, v_mps = 0, slip = 0;
  double disc_omega_radps = 0, sigma = 0;
  double clamp_force_N = 0, roller_mm = 0;
  double depth_mm = 0, draft_N = 0, terrain_mm = 0;
  // What the scenario varies on purpose, without any hidden effect (truth_columns.h): the
  // soil's slip (mean and variation along the row), the depth the terrain adds, the seedling's
  // thickness in the clamp's nip.
  double known_slip = 0, known_terrain_depth_mm = 0, known_nip_mm = 0;
  // The seedling in the clamp's nip, counted from 1 (0: empty), for the clamp's goal.
  std::size_t seedling_in_nip = 0;
};

class Plant {
 public:
  Plant(const PlantConfig& config, const ControllerConfig& board, std::uint64_t seed);

  void start_moving() { ground_.start(); }
  // A known weight hung on the load cell (commissioning), in newtons.
  void set_fixture_load_N(double load_N) { fixture_load_N_ = load_N; }
  // The feed from now on (a belt that runs empty is 100 %).
  void set_feed_miss_pct(double pct) { seedlings_.set_feed_miss_pct(pct); }
  void step(std::int64_t t_ns, std::int64_t dt_ns, PlantDevices& devices,
            hal::sim::SimEdgeSource& edges);

  [[nodiscard]] const PlantTruth& truth() const { return truth_; }
  [[nodiscard]] const Ground& ground() const { return ground_; }
  [[nodiscard]] const SeedlingProcess& seedlings() const { return seedlings_; }

 private:
  PlantConfig cfg_;
  ControllerConfig board_;
  Ground ground_;
  SoilWheelEncoder wheel_;
  DiscDriveModel disc_;
  LinearActuatorModel roller_;
  LinearActuatorModel depth_;
  SeedlingProcess seedlings_;
  GnssReceiverModel gnss_;
  std::mt19937_64 noise_rng_;
  double draft_share_ = 0.0;  // the soil draft's mobilised share (sim/soil/opener_draft.h)
  double draft_decay_dt_s_ = -1.0, draft_decay_ = 1.0;  // rest_decay of the last step's length
  double relaxation_N_ = 0.0;
  // The clamp law's power for the last compression: the nip holds still between seedlings, so
  // most substeps ask for the same value again (exact: the same argument, the same result).
  double clamp_compression_mm_ = 0.0, clamp_power_ = 0.0;
  double elastic_N_ = 0.0;  // the last substep's clamp force before relaxation: the nip's guess
  double relaxation2_N_ = 0.0;
  double fixture_load_N_ = 0.0;
  double draft_N_ = 0.0;  // the last substep's, for the sag in the working depth
  PlantTruth truth_;
  // The seedling photo-eye where seedlings leave the disc (hal::edge_line::kSeedlingSensor).
  void photo_eye(std::int64_t end_ns, hal::sim::SimEdgeSource& edges);
  std::size_t photo_eye_seen_ = 0;
  bool beam_broken_ = false;
  std::int64_t beam_clear_ns_ = 0;
};

}  // namespace planter::sim
