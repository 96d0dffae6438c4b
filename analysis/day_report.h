#pragma once
// What a recording longer than one window says across its length: each fitted parameter's
// track over the windows, and its verdict (day_tracks.h makes it).
#include <string>
#include <vector>

namespace planter::analysis {

struct Track {
  std::string name;
  std::string unit;
  std::vector<double> t_s, value, sd;  // per window: its middle, the refitted value, its sd
  std::string verdict;                 // "stable", "drifting", "changed", or "too few windows"
  double slope_per_h = 0.0;            // drifting
  double at_s = 0.0, at_sd_s = 0.0;    // changed: when, +- from the track's profile
  double before = 0.0, after = 0.0;    // changed: the levels either side
};

struct ChannelDay {
  std::vector<Track> tracks;
  std::string verdict;  // "stable", "drifting: ...", "changed at ...: ..."
};

struct DayReport {
  std::size_t windows = 0;
  double window_s = 0.0;
  std::size_t rows = 0;            // of the whole recording
  std::size_t untracked_rows = 0;  // a last piece shorter than a quarter window
  double duration_s = 0.0;
  std::vector<ChannelDay> channels;  // parallel to FitReport::channels
};

}  // namespace planter::analysis
