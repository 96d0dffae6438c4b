#pragma once
// One measured output of a subsystem and the nominal model that predicts it from recorded
// inputs (the nominal structures of docs/recording-format.md), with hooks where a candidate effect
// acts: on the input (delay, dead zone, play), on the state (rate limit), or on the output.
#include <optional>
#include <string>
#include <vector>

#include "analysis/disturbance.h"
#include "analysis/recording.h"

namespace planter::analysis {

struct ParamSpec {
  std::string name;
  std::string unit;
  double initial = 0.0;
  double lower = 0.0;
  double upper = 0.0;
  bool grid = false;  // non-smooth in the output (a delay, a gap, a step): searched on a grid
  // lower and upper are multiples of the recorded output's largest magnitude, not absolute:
  // a friction loop of 17 kN and one of 2 N are both inside the range (issue 32).
  bool of_output_size = false;
};

enum class EffectKind {
  kWheelRadius,     // v_wheel = (1 + g) v
  kSlipWithDraft,   // v_wheel = v (1 - s * depth_force / 1 kN)
  kDelay,           // input delayed by tau
  kDeadZone,        // zero for |u| <= w, u - w sign(u) beyond
  kBacklash,        // play of width gap between input and model
  kBacklashOutput,  // play of width gap between the model's output and what is measured
  kRateLimit,       // the state moves at most r per second
  kCoulomb,         // + F_c tanh(omega / 0.005)
  kStribeck,        // + [F_c + (F_s - F_c) exp(-(omega/omega_s)^2)] sign(omega)
  kOffset,          // + a
  kGain,            // * (1 + g)
  kDrift,           // + d * t
  kPeriodic,        // + A sin(2 pi f t + phi)
  kSaturation,      // min(y, limit): a sensor or output that reads no higher
  kQuantisation,    // round to q
  kRelaxation,      // a Maxwell branch takes share `frac` of the output with time constant tau
  kRelaxation2,     // a second branch beside it: a two-term Prony series
  kHysteresis,      // + H z, z the Bouc-Wen state of the input's displacement
  kSag,             // - c * load / 1 kN (compliance under the channel's load)
  kLoopFriction,    // under a speed loop: the speed w short of its command, held at rest
  kStiction,        // at standstill: the drive's effort K * command, held up to F_s
};

struct Effect;

// What an output effect may need besides the recording: the channel's load (N; sag, slip)
// and the speed its friction acts at.
struct OutputContext {
  const Recording& r;
  const std::vector<double>* load = nullptr;
  const std::vector<double>* speed = nullptr;
  const std::vector<Effect>* effects = nullptr;  // all of the channel's (Prony terms act together)
  const std::vector<double>* displacement =
      nullptr;  // what hysteresis follows (the clamp's roller)
  // Rows of `displacement` per row of the output: a thinned recording's is at its own rate
  // (Recording::travel).
  std::size_t displacement_stride = 1;
};

// One named effect, whole: what it is, its parameters and bounds, where and how it acts, and
// how a fit starts it. The library (effects.cpp) holds one entry per EffectKind, in the order
// the effects are applied.
struct EffectSpec {
  EffectKind kind;
  std::string name;       // the physics, in the machine's words
  std::string signature;  // what it looks like in the residual
  std::vector<ParamSpec> params;
  // Acts on the recorded input before the model, or on the model's output; an effect with
  // neither changes a channel's own dynamics and is applied there (rate limit, stiction).
  void (*on_input)(const Recording& r, const std::vector<double>& p,
                   std::vector<double>& u) = nullptr;
  void (*on_output)(const OutputContext& c, const std::vector<double>& p,
                    std::vector<double>& y) = nullptr;
  // Upper end of a grid parameter's search, from the data's input and output spans (nullptr:
  // the parameter's own upper bound).
  // The recorded output too: a quantiser's step can be no coarser than the grid its values lie
  // on.
  double (*grid_upper)(double in_span, double out_span,
                       const std::vector<double>& output) = nullptr;
  // A start read off the residual (nullptr: the parameters' initial values).
  std::vector<double> (*start)(const Recording& r, const std::vector<double>& residual) = nullptr;
  // Further starts tried from the data's own guess (a time constant can sit in any decade).
  std::vector<std::vector<double>> extra_starts{};
  // The simpler effect this one holds as a special case (Stribeck holds Coulomb): it must beat
  // that one by a clear margin, not only tie it.
  std::optional<EffectKind> extends{};
  // Only tried beside this one (a second Prony term beside the first).
  std::optional<EffectKind> needs{};
  // What a user would record to tell this effect from another that fits as well.
  std::string separating_experiment{};
  // The parameter that is the effect's size, zero where the effect is absent (a delay, a gap, a
  // fraction, an amplitude): an effect is kept only where it is resolved from zero (issue 52).
  // -1: none such (a rate limit is absent at an infinite rate).
  int size_param = 0;
};

struct Effect {
  const EffectSpec* spec = nullptr;
  std::vector<double> values;
};

class ChannelModel {
 public:
  virtual ~ChannelModel() = default;
  [[nodiscard]] virtual std::string subsystem() const = 0;
  [[nodiscard]] virtual std::string output() const = 0;
  [[nodiscard]] virtual std::string input() const = 0;  // the main recorded input
  // Columns this channel needs (output included); the channel is observable when all exist.
  [[nodiscard]] virtual std::vector<std::string> needs() const = 0;
  // Known disturbances the channel takes as inputs when the recording carries them (the
  // simulator's known_* columns, docs/recording-format.md): what the scenario varies on
  // purpose is then not a mismatch. A recording without them is fitted as before.
  [[nodiscard]] virtual std::vector<std::string> known_inputs() const { return {}; }
  // The unmeasured disturbance the channel carries where the recording lacks its known_*
  // column (a field log: disturbance.h), or nullptr (none, or the column is there as an input).
  [[nodiscard]] virtual const DisturbanceSpec* disturbance(const Recording&) const {
    return nullptr;
  }
  // Where disturbance() names one: whether the recording itself shows it is there (stems
  // counted through the clamp's nip). Then it is the first thing the residual is read as, and an
  // effect must earn its place beside it; otherwise the effects come first and it must earn its
  // place beside them (named_disturbance.h).
  [[nodiscard]] virtual bool disturbance_shown(const Recording&) const { return false; }
  // The residual's (prediction less record) sensitivity to that disturbance at each row, for
  // the nominal values and the prediction given.
  [[nodiscard]] virtual std::vector<double> disturbance_gain(
      const Recording& r, const std::vector<double>& /*nominal*/,
      const std::vector<double>& /*prediction*/) const {
    return std::vector<double>(r.size(), 0.0);
  }
  // The recorded displacement a rate-independent effect follows (the clamp's hysteresis
  // follows its roller), or none. A thinned recording carries its path apart (Recording::travel).
  [[nodiscard]] virtual std::string displacement() const { return {}; }
  [[nodiscard]] virtual std::vector<ParamSpec> nominal_params() const = 0;
  // The nominal structure in the machine's words ("the clamp law"), for what the summary says of
  // it.
  [[nodiscard]] virtual std::string law() const { return "the " + subsystem() + " model"; }
  // The candidate effects that make sense on this channel, given the recording's columns (an
  // effect driven by another signal, such as sag by the draft, needs that signal).
  [[nodiscard]] virtual std::vector<const EffectSpec*> candidates(const Recording& r) const = 0;
  // Free-run prediction of the output over all samples.
  virtual void simulate(const Recording& r, const std::vector<double>& nominal,
                        const std::vector<Effect>& effects, std::vector<double>& y) const = 0;
  // How many rows after row k the simulation of row k reads (a central difference reads one).
  // The fits simulate the calibration rows and this many more, not the held-out rest.
  [[nodiscard]] virtual std::size_t rows_ahead() const { return 0; }
  // Initial nominal values from the data (a rough guess for the solver).
  [[nodiscard]] virtual std::vector<double> initial_guess(const Recording& r) const;
  // Further starts of the nominal fit, across the ranges where its cost has more than one
  // valley (the clamp law's k, x0 and n trade against each other): the nominal is fitted from
  // each and the best kept, so no effect takes credit for escaping a local solution.
  [[nodiscard]] virtual std::vector<std::vector<double>> nominal_starts(const Recording&) const {
    return {};
  }
  // When a constant added to the output trades with the nominal's own constants (the clamp
  // law's contact point x0): the rows before `end` where, by the nominal values fitted beside
  // the offset, the subsystem is at zero load (the clamp open), the only place the offset is
  // told apart. nullopt: no trade, an offset is judged like any effect.
  [[nodiscard]] virtual std::optional<std::size_t> zero_load_rows(
      const Recording&, const std::vector<double>& /*nominal*/, std::size_t /*end*/) const {
    return std::nullopt;
  }
  // The residual's RMS that the recorded input's own measurement noise makes through the
  // nominal with these values (rows before `end`): an errors-in-variables floor. 0 where the
  // structure smooths its input; the disc torque differentiates its measured speed.
  [[nodiscard]] virtual double input_noise_rms(const Recording&, const std::vector<double>&,
                                               std::size_t /*end*/) const {
    return 0.0;
  }
};

// The rows before `end` where the nominal, with the values given, predicts no load: under 1 %
// of the recorded output's largest size. There a constant added to the output is seen alone.
std::size_t rows_at_zero_load(const ChannelModel& ch, const Recording& r,
                              const std::vector<double>& nominal, std::size_t end);

// The distance the machine has travelled at each row (m): the integral of the ground speed
// sensor's v_ground, or of v_wheel where there is none, 0 throughout where neither is recorded.
std::vector<double> distance_travelled(const Recording& r);

// Every channel of the nominal structures; the caller keeps those the recording observes.
std::vector<const ChannelModel*> all_channels();
const EffectSpec& effect_spec(EffectKind kind);

}  // namespace planter::analysis
