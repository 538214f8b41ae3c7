// The SVG charts of the bench report (bench_charts.h).
#include "bench/bench_charts.h"
#include "plot/plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace sl {

namespace {

// Okabe-Ito palette: distinguishable with the common colour-vision deficiencies.
const char* kColors[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"};
const char* kDashes[] = {"", "6 4", "2 3", "10 3 2 3"};

std::string num(double v, int digits = 3) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

// For legends: the sweep's values with the last part of their keys ("m=3", not "3").
std::string legendLabel(const BenchEntry& e) {
  std::string s = e.technique;
  for (const auto& kv : e.sweepPoint) s += " " + kv.first.substr(kv.first.rfind('.') + 1) + "=" + kv.second;
  return s;
}

// Axis ticks: "nice" linear steps, or 1-2-5 decades for a log axis.
std::vector<double> linearTicks(double lo, double hi) {
  double span = std::max(hi - lo, 1e-9), step = std::pow(10.0, std::floor(std::log10(span / 5)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (span / (step * m) <= 6) {
      step *= m;
      break;
    }
  std::vector<double> t;
  for (double v = std::ceil(lo / step) * step; v <= hi + step * 1e-6; v += step)
    t.push_back(std::abs(v) < step * 1e-6 ? 0 : v);
  return t;
}
std::vector<double> logTicks(double lo, double hi) {
  std::vector<double> t;
  for (double d = std::pow(10.0, std::floor(std::log10(lo))); d <= hi * 1.0001; d *= 10)
    for (double m : {1.0, 2.0, 5.0})
      if (d * m >= lo * 0.9999 && d * m <= hi * 1.0001) t.push_back(d * m);
  return t;
}

// Error axis: linear from 0, or logarithmic when the values span more than ~1.5 decades
// (one bad outlier would otherwise flatten every other point onto the zero line).
struct ErrorAxis {
  bool log = false;
  double lo = 0, hi = 1;
  explicit ErrorAxis(const std::vector<double>& values) {
    double mx = 0, mnPos = 1e30;
    for (double v : values) {
      mx = std::max(mx, v);
      if (v > 0) mnPos = std::min(mnPos, v);
    }
    log = mx > 0 && mnPos < 1e30 && mx / mnPos > 30;
    if (log) {
      lo = std::pow(10.0, std::floor(std::log10(mnPos)));
      hi = std::pow(10.0, std::ceil(std::log10(mx * 1.05)));
    } else {
      hi = mx > 0 ? mx * 1.15 : 1;
    }
  }
  // 0 at the bottom edge, 1 at the top; zero (or below lo) sits on the bottom edge of a log axis.
  double frac(double v) const {
    if (!log) return v / hi;
    v = std::max(v, lo);
    return (std::log(v) - std::log(lo)) / (std::log(hi) - std::log(lo));
  }
  std::vector<double> ticks() const {
    if (!log) return linearTicks(0, hi);
    std::vector<double> t;
    for (double d = lo; d <= hi * 1.0001; d *= 10) t.push_back(d);  // one tick per decade
    return t;
  }
};

// A chart's W x H canvas and the margins (left, right, top, bottom) around its plot rectangle.
struct ChartFrame {
  double W, H, L, R, T, B;
};

// The <svg> element's start and the white plot rectangle.
std::string chartStart(const ChartFrame& f, const char* ariaLabel) {
  std::ostringstream s;
  s << "<svg viewBox='0 0 " << f.W << " " << f.H << "' class='chart' role='img' aria-label='" << ariaLabel << "'>\n";
  s << "<rect x='" << f.L << "' y='" << f.T << "' width='" << f.W - f.L - f.R << "' height='" << f.H - f.T - f.B
    << "' fill='#fff' stroke='#888'/>\n";
  return s.str();
}

// A vertical grid line at x with its tick value under the plot.
std::string xGridLine(const ChartFrame& f, double x, double value) {
  std::ostringstream s;
  s << "<line x1='" << x << "' x2='" << x << "' y1='" << f.T << "' y2='" << f.H - f.B << "' class='grid'/><text x='"
    << x << "' y='" << f.H - f.B + 22 << "' text-anchor='middle'>" << num(value) << "</text>\n";
  return s.str();
}

// A horizontal grid line at y with its tick value left of the plot.
std::string yGridLine(const ChartFrame& f, double y, double value) {
  std::ostringstream s;
  s << "<line x1='" << f.L << "' x2='" << f.W - f.R << "' y1='" << y << "' y2='" << y << "' class='grid'/><text x='"
    << f.L - 8 << "' y='" << y + 5 << "' text-anchor='end'>" << num(value) << "</text>\n";
  return s.str();
}

struct Box {
  double x0, y0, x1, y1;
  bool hits(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Entries by median time, ties by error: the order the front is built and labels are placed in.
std::vector<size_t> byTimeThenError(const std::vector<BenchEntry>& es) {
  std::vector<size_t> order(es.size());
  for (size_t i = 0; i < es.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return es[a].msMedian != es[b].msMedian ? es[a].msMedian < es[b].msMedian
                                            : es[a].error.wrongPixelPct < es[b].error.wrongPixelPct;
  });
  return order;
}

// The Pareto front (lower error and lower time are both better), walked in `order`.
std::vector<size_t> paretoFront(const std::vector<BenchEntry>& es, const std::vector<size_t>& order) {
  std::vector<size_t> front;
  double best = 1e30;
  for (size_t i : order)
    if (es[i].error.wrongPixelPct < best) {
      front.push_back(i);
      best = es[i].error.wrongPixelPct;
    }
  return front;
}

// A point's label (tw x th) at the first candidate offset that stays inside the plot and overlaps
// the fewest points and earlier labels.
std::pair<double, double> labelPosition(double px, double py, double tw, double th, const Box& plot,
                                        const std::vector<Box>& taken) {
  const double cand[][2] = {{16, 5},  {-16 - tw, 5},   {-tw / 2, -16}, {-tw / 2, 28}, {14, -12},
                            {14, 22}, {-14 - tw, -12}, {-14 - tw, 22}, {14, 36},      {14, -26}};
  double lx = px + 14, ly = py + 5;
  int bestCost = 1 << 30;
  for (const auto& c : cand) {
    Box b{px + c[0], py + c[1] - th + 4, px + c[0] + tw, py + c[1] + 4};
    int cost = (b.x0 > plot.x0 && b.x1 < plot.x1 && b.y0 > plot.y0 && b.y1 < plot.y1) ? 0 : 100;
    for (const auto& o : taken) cost += b.hits(o) ? 1 : 0;
    if (cost < bestCost) {
      bestCost = cost;
      lx = px + c[0], ly = py + c[1];
    }
  }
  return {lx, ly};
}

std::string paretoLegend(double x, double y) {
  std::ostringstream s;
  s << "<g transform='translate(" << x << "," << y
    << ")'><rect x='-8' y='-6' width='254' "
       "height='50' fill='#fff' stroke='#ccc'/><circle cx='10' cy='10' r='9' class='ring'/><line x1='26' x2='50' "
       "y1='10' y2='10' class='pareto'/><text x='58' y='15' class='note'>Pareto front: nothing is</text>"
       "<text x='58' y='35' class='note'>both faster and more exact</text></g>\n";
  return s.str();
}

}  // namespace

std::vector<Style> entryStyles(const BenchResult& r) {
  std::vector<Style> out;
  std::map<std::string, int> seen;
  size_t colour = 0;
  std::map<std::string, size_t> firstColour;
  for (const auto& e : r.entries) {
    if (!firstColour.count(e.technique)) {
      firstColour[e.technique] = colour;
      size_t points = 0;
      for (const auto& o : r.entries) points += o.technique == e.technique;
      colour += (points + 3) / 4;
    }
    const int k = seen[e.technique]++;
    out.push_back({kColors[(firstColour[e.technique] + k / 4) % 8], kDashes[k % 4]});
  }
  return out;
}

std::string shortLabel(const BenchEntry& e) {
  std::string s = e.technique;
  for (const auto& kv : e.sweepPoint) s += " " + kv.second;
  return s;
}

std::string scatterSvg(const BenchResult& r, const std::vector<Style>& styles) {
  const double W = 960, H = 540, L = 80, R = 30, T = 30, B = 70;
  const auto& es = r.entries;
  double xmin = 1e30, xmax = 0;
  for (const auto& e : es) {
    xmin = std::min(xmin, std::max(e.msMedian, 1e-3));
    xmax = std::max(xmax, std::max(e.msMedian, 1e-3));
  }
  const bool logX = xmax / xmin > 6;
  double x0 = logX ? xmin / 1.3 : 0, x1 = logX ? xmax * 1.3 : xmax * 1.15;
  if (x1 <= x0) x1 = x0 + 1;
  std::vector<double> ys;
  for (const auto& e : es) ys.push_back(e.error.wrongPixelPct);
  ErrorAxis ya(ys);
  auto X = [&](double v) {
    v = std::max(v, 1e-3);
    double f = logX ? (std::log(v) - std::log(x0)) / (std::log(x1) - std::log(x0)) : (v - x0) / (x1 - x0);
    return L + f * (W - L - R);
  };
  auto Y = [&](double v) { return H - B - ya.frac(v) * (H - T - B); };
  const ChartFrame frame{W, H, L, R, T, B};
  std::ostringstream s;
  s << chartStart(frame, "error against time");
  for (double t : logX ? logTicks(x0, x1) : linearTicks(x0, x1)) s << xGridLine(frame, X(t), t);
  for (double t : ya.ticks()) s << yGridLine(frame, Y(t), t);
  s << "<text x='" << (L + W - R) / 2 << "' y='" << H - 20 << "' text-anchor='middle' class='axis'>time per frame, ms"
    << (logX ? " (log scale)" : "") << " — median, " << xmlEscaped(r.timer) << " timer</text>\n";
  s << "<text transform='translate(22," << (T + H - B) / 2
    << ") rotate(-90)' text-anchor='middle' class='axis'>wrong pixels, %" << (ya.log ? " (log scale)" : "")
    << "</text>\n";

  const std::vector<size_t> order = byTimeThenError(es);
  const std::vector<size_t> front = paretoFront(es, order);
  if (front.size() > 1) {
    s << "<polyline class='pareto' points='";
    for (size_t k = 0; k < front.size(); ++k) {
      if (k) s << X(es[front[k]].msMedian) << "," << Y(es[front[k - 1]].error.wrongPixelPct) << " ";
      s << X(es[front[k]].msMedian) << "," << Y(es[front[k]].error.wrongPixelPct) << " ";
    }
    s << "'/>\n";
  }
  std::vector<Box> taken;
  for (size_t i = 0; i < es.size(); ++i) {
    double px = X(es[i].msMedian), py = Y(es[i].error.wrongPixelPct);
    taken.push_back({px - 12, py - 12, px + 12, py + 12});
  }
  for (size_t i : order) {
    double px = X(es[i].msMedian), py = Y(es[i].error.wrongPixelPct);
    bool onFront = std::find(front.begin(), front.end(), i) != front.end();
    if (onFront) s << "<circle cx='" << px << "' cy='" << py << "' r='11' class='ring'/>";
    s << "<circle cx='" << px << "' cy='" << py << "' r='6' fill='" << styles[i].color
      << "' stroke='#fff' stroke-width='1.5'><title>" << xmlEscaped(es[i].label) << ": " << num(es[i].msMedian)
      << " ms, " << num(es[i].error.wrongPixelPct) << " % wrong</title></circle>\n";
    // Label: first candidate position that overlaps neither points nor earlier labels.
    std::string text = shortLabel(es[i]);
    const double tw = (onFront ? 8.4 : 7.8) * text.size(), th = 16;
    const auto [lx, ly] = labelPosition(px, py, tw, th, Box{L, T, W - R, H - B}, taken);
    taken.push_back({lx, ly - th + 4, lx + tw, ly + 4});
    s << "<text x='" << lx << "' y='" << ly << "' class='pt" << (onFront ? " front" : "") << "'>" << xmlEscaped(text)
      << "</text>\n";
  }
  s << paretoLegend(W - R - 272, T + 10) << "</svg>\n";
  return s.str();
}

std::string convergenceSvg(const BenchResult& r, const std::vector<Style>& styles) {
  size_t longest = 0;
  for (const auto& e : r.entries) longest = std::max(longest, legendLabel(e).size());
  const double W = 960, H = std::max(420.0, 120.0 + 22.0 * r.entries.size()), L = 80, T = 20, B = 60;
  const double R = std::clamp(76.0 + 7.6 * longest, 250.0, 480.0);
  int n = 1;
  for (const auto& e : r.entries) n = std::max<int>(n, static_cast<int>(e.convergence.size()));
  std::vector<double> ys;
  for (const auto& e : r.entries) ys.insert(ys.end(), e.convergence.begin(), e.convergence.end());
  ErrorAxis ya(ys);
  auto X = [&](double f) { return L + (n > 1 ? (f - 1) / (n - 1) : 0.5) * (W - L - R); };
  auto Y = [&](double v) { return H - B - ya.frac(v) * (H - T - B); };
  const ChartFrame frame{W, H, L, R, T, B};
  std::ostringstream s;
  s << chartStart(frame, "error per frame");
  for (double t : linearTicks(1, n))
    if (t >= 1 && std::abs(t - std::round(t)) < 1e-9) s << xGridLine(frame, X(t), t);
  for (double t : ya.ticks()) s << yGridLine(frame, Y(t), t);
  s << "<text x='" << (L + W - R) / 2 << "' y='" << H - 16 << "' text-anchor='middle' class='axis'>frame "
    << (!r.options.path.empty()
            ? "along the path at 30 fps" +
                  (r.options.approach > 0
                       ? " (history filled by the " + std::to_string(r.options.approach) + " path frames before)"
                       : std::string(" (history starts empty)"))
        : r.options.approach > 0 ? "(still camera after " + std::to_string(r.options.approach) +
                                       " frames of camera rotation: filled history)"
                                 : "(after warm-up; history starts empty at frame 1)")
    << "</text>\n";
  s << "<text transform='translate(22," << (T + H - B) / 2
    << ") rotate(-90)' text-anchor='middle' class='axis'>wrong pixels, %" << (ya.log ? " (log scale)" : "")
    << "</text>\n";
  for (size_t i = 0; i < r.entries.size(); ++i) {
    const auto& c = r.entries[i].convergence;
    s << "<polyline fill='none' stroke='" << styles[i].color << "' stroke-width='2.5' stroke-dasharray='"
      << styles[i].dash << "' points='";
    for (size_t f = 0; f < c.size(); ++f) s << X(f + 1.0) << "," << Y(c[f]) << " ";
    s << "'><title>" << xmlEscaped(r.entries[i].label) << "</title></polyline>\n";
    if (c.size() == 1)
      s << "<circle cx='" << X(1) << "' cy='" << Y(c[0]) << "' r='4' fill='" << styles[i].color << "'/>";
    double ly = T + 10 + i * 22.0;
    s << "<line x1='" << W - R + 16 << "' x2='" << W - R + 52 << "' y1='" << ly << "' y2='" << ly << "' stroke='"
      << styles[i].color << "' stroke-width='3' stroke-dasharray='" << styles[i].dash << "'/><text x='" << W - R + 60
      << "' y='" << ly + 5 << "'>" << xmlEscaped(legendLabel(r.entries[i])) << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace sl
