#pragma once
// The figures a run's summary gives at its operating point, as the multi-run commands
// (sensitivity, montecarlo) report them: one definition, so their tables agree.
#include <array>
#include <cstddef>

#include "sim/runner/summary.h"

namespace planter::sim {

struct RunFigure {
  const char* name;
  const char* unit;
  const char* column;  // in the commands' CSV files
};
inline constexpr std::size_t kRunFigureCount = 3;
inline constexpr std::array<RunFigure, kRunFigureCount> kRunFigures{
    {{"uprightness", "%", "uprightness_pct"},
     {"damage", "%", "damage_pct"},
     {"turned in the clamp", "%", "turned_in_clamp_pct"}}};

inline std::array<double, kRunFigureCount> run_figures(const Summary& s) {
  return {s.uprightness_pct, s.damage_pct,
          s.seedlings_planted > 0 ? 100.0 * static_cast<double>(s.seedlings_turned_in_clamp) /
                                        static_cast<double>(s.seedlings_planted)
                                  : 0.0};
}

}  // namespace planter::sim
