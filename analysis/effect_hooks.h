#pragma once
// Where the candidate effects act in a channel's simulation (see channel_model.h).
#include <string>
#include <vector>

#include "analysis/channel_model.h"

namespace planter::analysis {

const Effect* find_effect(const std::vector<Effect>& fx, EffectKind kind);
// The two branches of a Prony series are interchangeable: the faster is named first.
void order_prony_terms(std::vector<Effect>& fx, std::vector<std::vector<double>>& sd);
// u read `shift_s` earlier (later when negative), linear between rows and held at the ends:
// the transport delay's form, and the drives' known command path (channels.cpp).
void shift_in_time(const Recording& r, double shift_s, std::vector<double>& u);
// Delay, dead zone and play, applied to a recorded input.
std::vector<double> transform_input(const Recording& r, const std::vector<double>& u,
                                    const std::vector<Effect>& fx);
// Everything that acts on the output; `load` (N) for sag and slip, `speed` for friction, and
// the column a rate-independent effect follows (`displacement`; at its own rate when the
// recording was thinned: Recording::travel).
void apply_output(const Recording& r, const std::vector<Effect>& fx,
                  const std::vector<double>* load, const std::vector<double>* speed,
                  std::vector<double>& y, const std::string& displacement = {});

}  // namespace planter::analysis
