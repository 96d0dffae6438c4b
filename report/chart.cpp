#include "report/chart.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <limits>

#include "report/html_text.h"

namespace planter::report {

// Generated from libjs-dygraphs (cmake/embed_text.cmake, sim/CMakeLists.txt).
std::string dygraphs_library();
std::string dygraphs_library_css();

namespace {

// A JavaScript string literal that is safe inside <script>: no quote, backslash, control
// character or '<' left bare.
std::string js_string(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    const auto u = static_cast<unsigned char>(c);
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (u < 0x20 || c == '<' || c == '>' || c == '&') {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", u);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  // "%.6g" (std::to_chars' general format with a precision is printf's %g, C++17
  // [charconv.to.chars]) without printf's cost, which was most of writing a report.
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 6);
  return std::string(buf, r.ptr);
}

std::string string_array(const std::vector<std::string>& items) {
  std::string out = "[";
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i) out += ',';
    out += js_string(items[i]);
  }
  return out + "]";
}

std::string markers(const std::vector<Marker>& ms) {
  std::string out = "[";
  for (std::size_t i = 0; i < ms.size(); ++i) {
    out += i ? ",[" : "[";
    out += number(ms[i].at);
    out += ',';
    out += js_string(ms[i].colour);
    out += ',';
    out += js_string(ms[i].label);
    out += ']';
  }
  return out + "]";
}

constexpr const char* kPageScript = R"js(
function planterChart(id, o) {
  // A mark's label stays inside the plot (left of its line where the right edge would cut it)
  // and below any label it would cover; where each went is kept on the chart's element
  // (data-marks: x, y, width, height from its top left) for the phone test to check.
  var marks = function(ctx, area, g) {
    var placed = [], h = 12;
    var put = function(text, x, y) {
      var w = ctx.measureText(text).width;
      if (x + w > area.x + area.w) x = Math.max(area.x, x - w - 8);
      for (var k = 0; k < 8; ++k) {
        var hit = placed.some(function(r) {
          return x < r[0] + r[2] && r[0] < x + w && y - h < r[1] + r[3] && r[1] < y;
        });
        if (!hit) break;
        y += h + 2;
      }
      ctx.fillText(text, x, y);
      placed.push([x, y - h, w, h]);
    };
    ctx.save();
    ctx.setLineDash([6, 4]);
    ctx.lineWidth = 1.5;
    ctx.font = h + 'px sans-serif';
    o.xm.forEach(function(m) {
      var x = g.toDomXCoord(m[0]);
      if (x < area.x || x > area.x + area.w) return;
      ctx.strokeStyle = m[1]; ctx.fillStyle = m[1];
      ctx.beginPath(); ctx.moveTo(x, area.y); ctx.lineTo(x, area.y + area.h); ctx.stroke();
      put(m[2], x + 4, area.y + h + 1);
    });
    o.ym.forEach(function(m) {
      var y = g.toDomYCoord(m[0]);
      if (y < area.y || y > area.y + area.h) return;
      ctx.strokeStyle = m[1]; ctx.fillStyle = m[1];
      ctx.beginPath(); ctx.moveTo(area.x, y); ctx.lineTo(area.x + area.w, y); ctx.stroke();
      put(m[2], area.x + 6, y - 4);
    });
    ctx.restore();
    document.getElementById(id).dataset.marks = JSON.stringify(placed);
  };
  new Dygraph(document.getElementById(id), o.data, {
    title: o.title, xlabel: o.xlabel, ylabel: o.ylabel, labels: o.labels, colors: o.colors,
    customBars: o.bands, stepPlot: o.steps, fillGraph: o.steps, valueRange: o.range,
    legend: 'always', labelsDiv: id + '-legend', drawGapEdgePoints: true,
    underlayCallback: marks, axes: {y: {axisLabelWidth: 64}}, xLabelHeight: 16, yLabelWidth: 18
  });
}
)js";

constexpr const char* kPageStyle = R"css(
.chart { margin: 8px 0 22px 0; }
.chart .plot { width: 100%; max-width: 900px; height: 260px; }
.chart .legend { font: 12px sans-serif; min-height: 16px; margin-left: 70px; }
.chart .caption { font: 12px sans-serif; color: #444; margin-left: 70px; }
.dygraph-title { font-size: 15px; }
.dygraph-label { font-size: 12px; }
)css";

}  // namespace

std::string ChartPage::head() {
  return "<style>" + dygraphs_library_css() + kPageStyle + "</style><script>" + dygraphs_library() +
         "</script><script>" + kPageScript + "</script>";
}

std::string ChartPage::chart(const ChartSpec& spec, const std::string& x_label,
                             const std::string& y_label, const std::vector<std::string>& labels,
                             const std::vector<std::string>& colours, const std::string& data,
                             bool bands, bool steps, const std::string& caption) {
  const std::string id = "chart" + std::to_string(next_id_++);
  std::string range = "null";
  if (spec.y_max > spec.y_min) {
    range = "[";
    range += number(spec.y_min);
    range += ',';
    range += number(spec.y_max);
    range += ']';
  }
  std::string out = "<div class='chart'><div class='plot' id='" + id +
                    "'></div><div class='legend' id='" + id + "-legend'></div>";
  if (!caption.empty()) out += "<div class='caption'>" + html_escape(caption) + "</div>";
  out += "<script>planterChart('" + id + "', {title: " + js_string(spec.title) +
         ", xlabel: " + js_string(x_label) + ", ylabel: " + js_string(y_label) +
         ", labels: " + string_array(labels) + ", colors: " + string_array(colours) +
         ", bands: " + (bands ? "true" : "false") + ", steps: " + (steps ? "true" : "false") +
         ", range: " + range + ", xm: " + markers(spec.x_markers) +
         ", ym: " + markers(spec.y_markers) + ", data: " + data + "});</script></div>\n";
  return out;
}

std::string ChartPage::lines(const ChartSpec& spec, const std::vector<double>& x,
                             const std::vector<Line>& lines, std::size_t max_points) {
  std::vector<std::string> labels{spec.x_label}, colours;
  for (const Line& l : lines) {
    labels.emplace_back(l.label);
    colours.emplace_back(l.colour);
  }
  const std::size_t n = x.size();
  const bool bands = n > max_points;
  const std::size_t buckets = bands ? max_points : n;
  std::string data = "[";
  for (std::size_t b = 0; b < buckets; ++b) {
    const std::size_t from = bands ? b * n / buckets : b;
    const std::size_t to = bands ? (b + 1) * n / buckets : b + 1;
    if (from >= to) continue;
    data += b ? ",[" : "[";
    data += number(x[from]);
    for (const Line& l : lines) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo, sum = 0;
      std::size_t count = 0;
      for (std::size_t i = from; i < to && i < l.y->size(); ++i) {
        const double v = (*l.y)[i];
        if (!std::isfinite(v)) continue;
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        sum += v;
        ++count;
      }
      const double mean = count ? sum / static_cast<double>(count) : std::nan("");
      data += ',';
      if (!bands) {
        data += number(mean);
      } else if (count) {
        data += '[';
        data += number(lo);
        data += ',';
        data += number(mean);
        data += ',';
        data += number(hi);
        data += ']';
      } else {
        data += "null";
      }
    }
    data += "]";
  }
  data += "]";
  const std::string y_label =
      spec.y_unit.empty() ? spec.title : spec.title + " [" + spec.y_unit + "]";
  const std::string caption =
      (spec.note.empty() ? "" : spec.note + " ") +
      (bands ? "Thinned to " + std::to_string(buckets) + " points of " + std::to_string(n) +
                   ": each line is its mean, the band its minimum to maximum. Drag to zoom, "
                   "double-click to reset."
             : std::string("Drag to zoom, double-click to reset."));
  return chart(spec, spec.x_label, y_label, labels, colours, data, bands, false, caption);
}

std::string ChartPage::histogram(const ChartSpec& spec, const std::vector<double>& values,
                                 double lo, double hi, int bins) {
  bins = std::max(1, bins);
  std::vector<int> counts(static_cast<std::size_t>(bins), 0);
  int below = 0, above = 0;
  for (const double v : values) {
    if (!std::isfinite(v)) continue;
    if (v < lo) ++below;
    if (v >= hi) ++above;
    const int b =
        std::clamp(static_cast<int>(std::floor((v - lo) / (hi - lo) * bins)), 0, bins - 1);
    ++counts[static_cast<std::size_t>(b)];
  }
  const double width = (hi - lo) / bins;
  std::string data = "[";
  for (int b = 0; b <= bins; ++b) {
    const int c = counts[static_cast<std::size_t>(std::min(b, bins - 1))];
    data += b ? ",[" : "[";
    data += number(lo + b * width);
    data += ',';
    data += std::to_string(c);
    data += ']';
  }
  data += "]";
  std::string caption = (spec.note.empty() ? "" : spec.note + " ") + std::to_string(values.size()) +
                        " values in bins of " + number(width);
  if (below || above)
    caption += "; " + std::to_string(below) + " below " + number(lo) +
               " counted in the first bin, " + std::to_string(above) + " at or above " +
               number(hi) + " in the last";
  caption += ".";
  ChartSpec s = spec;
  s.y_min = 0;
  s.y_max = 0;
  return chart(s, spec.x_label, "count", {spec.x_label, "count"}, {"#4a7"}, data, false, true,
               caption);
}

}  // namespace planter::report
