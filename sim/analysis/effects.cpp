// The library of named candidate effects and the hooks that apply them.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "sim/analysis/effect_hooks.h"

namespace planter::analysis {
namespace {

constexpr double kTwoPi = 6.283185307179586;

const std::vector<EffectSpec>& library() {
  static const std::vector<EffectSpec> lib = {
      {EffectKind::kWheelRadius,
       "wrong effective wheel radius",
       "speed error proportional to speed",
       {{"radius_error", "1", 0.0, -0.3, 0.3}}},
      {EffectKind::kSlipWithDraft,
       "wheel slip growing with draft load",
       "speed deficit proportional to speed times opener draft",
       {{"slip_per_kN", "1/kN", 0.0, -0.5, 0.5}}},
      {EffectKind::kDelay,
       "transport delay",
       "residual follows the input's derivative",
       {{"delay_s", "s", 0.0, 0.0, 0.5, true}}},
      {EffectKind::kDeadZone,
       "dead zone",
       "no response to small inputs",
       {{"width", "input units", 0.0, 0.0, 0.0, true}}},
      {EffectKind::kBacklash,
       "backlash (play)",
       "lag at every reversal of the input",
       {{"gap", "input units", 0.0, 0.0, 0.0, true}}},
      {EffectKind::kRateLimit,
       "rate limit",
       "residual at large steps, linear ramps",
       {{"rate_per_s", "output units/s", 1.0, 1e-3, 1e4}}},
      {EffectKind::kCoulomb,
       "Coulomb friction",
       "a step in the residual at each speed reversal",
       // Friction opposes motion: the drive pays it in the direction of motion, never gets it.
       {{"coulomb", "output units", 0.0, 0.0, 100.0}}},
      {EffectKind::kStribeck,
       "Stribeck friction",
       "extra resistance at low speed",
       {{"stribeck_extra", "output units", 0.0, 0.0, 100.0},
        {"stribeck_speed", "input units", 0.1, 0.005, 5.0}}},
      {EffectKind::kOffset,
       "sensor offset",
       "a constant residual",
       {{"offset", "output units", 0.0, -1e4, 1e4}}},
      {EffectKind::kGain,
       "sensor gain error",
       "residual proportional to the output",
       {{"gain_error", "1", 0.0, -0.5, 0.5}}},
      {EffectKind::kDrift,
       "sensor drift",
       "a residual growing linearly with time",
       {{"drift_per_s", "output units/s", 0.0, -10.0, 10.0}}},
      {EffectKind::kPeriodic,
       "periodic disturbance (vibration)",
       "a peak in the residual spectrum",
       {{"amplitude", "output units", 0.0, 0.0, 1e4},
        {"frequency_hz", "Hz", 1.0, 0.01, 50.0},
        {"phase_rad", "rad", 0.0, -20.0, 20.0}}},
      {EffectKind::kQuantisation,
       "quantisation",
       "a staircase residual, uniform within a step",
       {{"step", "output units", 0.0, 0.0, 0.0, true}}},
      {EffectKind::kRelaxation,
       "viscoelastic relaxation (creep) of the clamp",
       "output decays towards a lower level after each load change",
       {{"fraction", "1", 0.1, 0.0, 0.9}, {"tau_s", "s", 2.0, 0.05, 60.0}}},
      {EffectKind::kSag,
       "actuator compliance (sag) under load",
       "residual proportional to the load on the actuator",
       {{"sag_per_kN", "output units/kN", 0.0, -100.0, 100.0}}},
      {EffectKind::kStiction,
       "stiction (the disc held by static friction)",
       "torque while the speed is zero and the command is not",
       {{"effort_gain", "N m s/rad", 10.0, 0.0, 1e3}, {"breakaway", "N m", 1.0, 0.0, 100.0}}},
  };
  return lib;
}

}  // namespace

const EffectSpec& effect_spec(EffectKind kind) {
  for (const auto& e : library())
    if (e.kind == kind) return e;
  throw std::logic_error("effect kind without an entry in the library");
}

const Effect* find_effect(const std::vector<Effect>& fx, EffectKind kind) {
  for (const auto& e : fx)
    if (e.spec->kind == kind) return &e;
  return nullptr;
}

std::vector<double> transform_input(const Recording& r, const std::vector<double>& u,
                                    const std::vector<Effect>& fx) {
  std::vector<double> out = u;
  const std::size_t n = u.size();
  if (const Effect* e = find_effect(fx, EffectKind::kDelay); e && e->values[0] > 0.0) {
    const double tau = e->values[0];
    std::size_t j = 0;
    for (std::size_t k = 0; k < n; ++k) {
      const double when = r.t[k] - tau;
      if (when <= r.t[0]) {
        out[k] = u[0];
        continue;
      }
      while (j + 1 < n && r.t[j + 1] < when) ++j;
      const double a = (when - r.t[j]) / (r.t[j + 1] - r.t[j]);
      out[k] = u[j] + a * (u[j + 1] - u[j]);
    }
  }
  if (const Effect* e = find_effect(fx, EffectKind::kDeadZone); e && e->values[0] > 0.0) {
    for (auto& v : out)
      if (std::abs(v) < e->values[0]) v = 0.0;
  }
  if (const Effect* e = find_effect(fx, EffectKind::kBacklash); e && e->values[0] > 0.0) {
    const double half = 0.5 * e->values[0];
    double y = out[0];
    for (auto& v : out) {
      y = std::clamp(y, v - half, v + half);
      v = y;
    }
  }
  return out;
}

void apply_output(const Recording& r, const std::vector<Effect>& fx,
                  const std::vector<double>* load, const std::vector<double>* speed,
                  std::vector<double>& y) {
  const std::size_t n = y.size();
  if (const Effect* e = find_effect(fx, EffectKind::kRelaxation)) {
    const double frac = e->values[0], tau = e->values[1];
    // The relaxed share follows frac * y with time constant tau and is no longer carried:
    // a step in load gives the full force, which then decays towards (1 - frac) of it.
    double relaxed = frac * y[0];
    for (std::size_t k = 0; k < n; ++k) {
      const double dt = k > 0 ? r.t[k] - r.t[k - 1] : 0.0;
      relaxed += (frac * y[k] - relaxed) * std::min(1.0, dt / tau);
      // A contact force cannot pull: the relaxed branch lowers the output towards zero, never
      // past it (an opened clamp reads nothing while the branch recovers).
      const double relaxed_y = y[k] - relaxed;
      y[k] = y[k] >= 0.0 ? std::max(0.0, relaxed_y) : std::min(0.0, relaxed_y);
    }
  }
  if (load) {
    if (const Effect* e = find_effect(fx, EffectKind::kSag))
      for (std::size_t k = 0; k < n; ++k) y[k] -= e->values[0] * (*load)[k] / 1000.0;
    if (const Effect* e = find_effect(fx, EffectKind::kSlipWithDraft))
      for (std::size_t k = 0; k < n; ++k) y[k] *= 1.0 - e->values[0] * (*load)[k] / 1000.0;
  }
  if (speed) {
    const Effect* c = find_effect(fx, EffectKind::kCoulomb);
    const Effect* s = find_effect(fx, EffectKind::kStribeck);
    for (std::size_t k = 0; k < n && (c || s); ++k) {
      const double w = (*speed)[k];
      const double sgn = std::tanh(w / 0.005);  // sharp: the disc turns at only ~0.3 rad/s
      if (c) y[k] += c->values[0] * sgn;
      if (s) y[k] += s->values[0] * std::exp(-(w / s->values[1]) * (w / s->values[1])) * sgn;
    }
  }
  if (const Effect* e = find_effect(fx, EffectKind::kWheelRadius))
    for (auto& v : y) v *= 1.0 + e->values[0];
  if (const Effect* e = find_effect(fx, EffectKind::kGain))
    for (auto& v : y) v *= 1.0 + e->values[0];
  if (const Effect* e = find_effect(fx, EffectKind::kOffset))
    for (auto& v : y) v += e->values[0];
  if (const Effect* e = find_effect(fx, EffectKind::kDrift))
    for (std::size_t k = 0; k < n; ++k) y[k] += e->values[0] * (r.t[k] - r.t[0]);
  if (const Effect* e = find_effect(fx, EffectKind::kPeriodic))
    for (std::size_t k = 0; k < n; ++k)
      y[k] += e->values[0] * std::sin(kTwoPi * e->values[1] * r.t[k] + e->values[2]);
  if (const Effect* e = find_effect(fx, EffectKind::kQuantisation); e && e->values[0] > 0.0)
    for (auto& v : y) v = e->values[0] * std::round(v / e->values[0]);
}

}  // namespace planter::analysis
