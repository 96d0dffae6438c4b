#pragma once
// Charts for the self-contained HTML reports, drawn by dygraphs (Debian's libjs-dygraphs,
// inlined at build time: no network, no CDN). dygraphs was made for long time series: it zooms
// (drag; double-click to reset), pans (shift-drag), shows values under the cursor, leaves a gap
// where a value is undefined (NaN here), and draws a band from [low, mid, high] triples, which
// is how a thinned series keeps its extremes. What it does not draw, marker lines (set-points,
// ceilings, thresholds, the held-out boundary), a few lines of page script add.
#include <string>
#include <vector>

namespace planter::report {

struct Line {
  const std::vector<double>* y;  // NaN: undefined there (drawn as a gap)
  const char* colour;
  const char* label;
};

// A value marked across the chart: a set-point or ceiling (on y), a boundary (on x).
struct Marker {
  double at;
  const char* colour;
  std::string label;
};

struct ChartSpec {
  std::string title;
  std::string y_unit;           // "" for a ratio
  std::string x_label;          // with its unit: "time [s]"
  double y_min = 0, y_max = 0;  // y_max <= y_min: from the data
  std::vector<Marker> x_markers, y_markers;
  std::string note;  // a sentence under the chart, before how to use it
};

// One report page's charts: each gets its own element id.
class ChartPage {
 public:
  // The library and the page's chart script, for the page's <head>.
  static std::string head();
  // Lines over a shared x. Over max_points, the x range is cut into max_points buckets and each
  // line drawn as its bucket mean inside a min-max band.
  std::string lines(const ChartSpec& spec, const std::vector<double>& x,
                    const std::vector<Line>& lines, std::size_t max_points = 2000);
  // Counts of values in bins from lo to hi, over spec.x_label (with its unit); values outside go
  // to the end bins (the caption says how many). spec.y_unit is not used.
  std::string histogram(const ChartSpec& spec, const std::vector<double>& values, double lo,
                        double hi, int bins);

 private:
  std::string chart(const ChartSpec& spec, const std::string& x_label, const std::string& y_label,
                    const std::vector<std::string>& labels, const std::vector<std::string>& colours,
                    const std::string& data, bool bands, bool steps, const std::string& caption);
  int next_id_ = 0;
};

}  // namespace planter::report
