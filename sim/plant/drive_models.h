#pragma once
// Physical behaviour behind the simulated CiA 402 drives.
#include <algorithm>
#include <cmath>
#include <deque>

#include "sim/plant/plant_config.h"

namespace planter::sim {

// Disc drive train: a velocity loop (first-order lag T_d, saturation) on the disc inertia with
// viscous damping; optional Coulomb and Stribeck friction, backlash, a dead zone and a command
// delay.
// The dead zone of an input: zero in [-below, +above], the input less the band outside it.
// A negative `below` means a symmetric band (the same width as above).
inline double dead_zone(double u, double above, double below) {
  const double lo = below < 0.0 ? above : below;
  if (u > above) return u - above;
  if (u < -lo) return u + lo;
  return 0.0;
}

class DiscDriveModel {
 public:
  explicit DiscDriveModel(const DriveModelConfig& d, const Effects& e) : d_(d), e_(e) {}

  void step(double omega_target, bool enabled, bool quick_stop, double dt_s) {
    // Command delay (transport delay between the drive's set-point and its loop).
    if (e_.command_delay_s > 0.0) {
      delayed_.push_back(omega_target);
      const auto n = static_cast<std::size_t>(std::lround(e_.command_delay_s / dt_s));
      while (delayed_.size() > n + 1) delayed_.pop_front();
      omega_target = delayed_.front();
    }
    // Dead zone in the control-textbook form (Tao & Kokotovic, "Adaptive Control of Systems
    // with Actuator and Sensor Nonlinearities", 1996, ch. 2): nothing inside the band, the
    // set-point less the band beyond it; each side has its own width.
    omega_target = dead_zone(omega_target, e_.disc_deadzone_radps, e_.disc_deadzone_neg_radps);
    const double target =
        enabled ? std::clamp(omega_target, -d_.disc_omega_max_radps, d_.disc_omega_max_radps) : 0.0;
    const double tau = quick_stop ? 0.02 : d_.disc_time_constant_s;
    // Loop gain chosen so the nominal response is the first-order lag T_d.
    const double gain = d_.disc_inertia_kgm2 / tau;
    double torque =
        enabled || quick_stop ? gain * (target - omega_) + d_.disc_damping_Nms * target : 0.0;
    const double stribeck_speed = omega_ / e_.disc_stribeck_radps;
    const double dry =
        e_.disc_coulomb_Nm + e_.disc_stribeck_Nm * std::exp(-stribeck_speed * stribeck_speed);
    const double friction = dry * (std::abs(omega_) > 1e-4 ? std::copysign(1.0, omega_) : 0.0);
    double accel = (torque - d_.disc_damping_Nms * omega_ - friction) / d_.disc_inertia_kgm2;
    if (std::abs(omega_) <= 1e-4 && std::abs(torque) <= dry) accel = 0.0;  // stuck
    const double previous = omega_;
    omega_ += accel * dt_s;
    if (previous != 0.0 && omega_ * previous < 0.0 && std::abs(torque) <= dry) omega_ = 0.0;
    torque_Nm_ = torque;
    motor_angle_rad_ += omega_ * dt_s;
    // Backlash: the disc follows the motor only when the play is taken up.
    const double gap = e_.disc_backlash_rad;
    if (motor_angle_rad_ - disc_angle_rad_ > gap / 2) disc_angle_rad_ = motor_angle_rad_ - gap / 2;
    if (disc_angle_rad_ - motor_angle_rad_ > gap / 2) disc_angle_rad_ = motor_angle_rad_ + gap / 2;
    disc_omega_ = (disc_angle_rad_ - previous_disc_angle_) / dt_s;
    previous_disc_angle_ = disc_angle_rad_;
  }
  [[nodiscard]] double omega() const { return omega_; }  // motor side, as the drive measures
  [[nodiscard]] double disc_omega() const { return disc_omega_; }  // the disc itself
  [[nodiscard]] double motor_angle() const { return motor_angle_rad_; }
  [[nodiscard]] double disc_angle() const { return disc_angle_rad_; }
  [[nodiscard]] double torque_Nm() const { return torque_Nm_; }

 private:
  DriveModelConfig d_;
  Effects e_;
  std::deque<double> delayed_;
  double omega_ = 0.0;
  double disc_omega_ = 0.0;
  double motor_angle_rad_ = 0.0;
  double disc_angle_rad_ = 0.0;
  double previous_disc_angle_ = 0.0;
  double torque_Nm_ = 0.0;
};

// A linear position actuator: first-order lag T_a towards its set-point with a rate limit.
class LinearActuatorModel {
 public:
  // Travel between the end stops [min_mm, max_mm] (infinite by default).
  explicit LinearActuatorModel(double time_constant_s, double min_mm = -1e9, double max_mm = 1e9)
      : tau_s_(time_constant_s), min_mm_(min_mm), max_mm_(max_mm) {}
  void step(double setpoint_mm, double rate_limit_mm_per_s, bool enabled, double dt_s) {
    if (!enabled) return;  // holds (quick stop or disabled: brake engaged)
    double v = (setpoint_mm - x_mm_) / tau_s_;
    if (rate_limit_mm_per_s > 0.0) v = std::clamp(v, -rate_limit_mm_per_s, rate_limit_mm_per_s);
    x_mm_ = std::clamp(x_mm_ + v * dt_s, min_mm_, max_mm_);
  }
  [[nodiscard]] double position_mm() const { return x_mm_; }
  void set_position_mm(double x) { x_mm_ = x; }

 private:
  double tau_s_;
  double min_mm_;
  double max_mm_;
  double x_mm_ = 0.0;
};

}  // namespace planter::sim
