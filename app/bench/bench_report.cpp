// The HTML report of `shadowlab bench`: one self-contained page (inline CSS + SVG, a few lines of
// inline script to sort the table, no libraries, no network) plus PNG images and results.csv.
#include "bench/bench.h"
#include "plot/plot.h"
#include "cli/args.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sl {

namespace {

// Excess mean change per frame shown white in the flicker map: an edge pixel the truth flips
// once in a path of 60 frames changes by ~0.017 per frame.
constexpr float kFlickerFullScale = 0.1f;

// Okabe-Ito palette: distinguishable with the common colour-vision deficiencies.
const char* kColors[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442"};
const char* kDashes[] = {"", "6 4", "2 3", "10 3 2 3"};

std::string num(double v, int digits = 3) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}
std::string fixed(double v, int decimals) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// "pcf 1024": technique plus sweep values only, for point labels and legends.
std::string shortLabel(const BenchEntry& e) {
  std::string s = e.technique;
  for (const auto& kv : e.sweepPoint) s += " " + kv.second;
  return s;
}

// For legends: the sweep's values with the last part of their keys ("m=3", not "3").
std::string legendLabel(const BenchEntry& e) {
  std::string s = e.technique;
  for (const auto& kv : e.sweepPoint) s += " " + kv.first.substr(kv.first.rfind('.') + 1) + "=" + kv.second;
  return s;
}

struct Style {
  std::string color, dash;
};

// Colour per technique and dash pattern per position in its sweep while that tells every entry
// apart; a technique with more than four sweep points takes the next colours too.
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

struct Box {
  double x0, y0, x1, y1;
  bool hits(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

std::string scatterSvg(const BenchResult& r, const std::vector<Style>& styles) {
  const double W = 960, H = 540, L = 80, R = 30, T = 30, B = 70;
  const auto& es = r.entries;
  double xmin = 1e30, xmax = 0, ymax = 0;
  for (const auto& e : es) {
    xmin = std::min(xmin, std::max(e.msMedian, 1e-3));
    xmax = std::max(xmax, std::max(e.msMedian, 1e-3));
    ymax = std::max(ymax, e.error.wrongPixelPct);
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
  std::ostringstream s;
  s << "<svg viewBox='0 0 " << W << " " << H << "' class='chart' role='img' aria-label='error against time'>\n";
  s << "<rect x='" << L << "' y='" << T << "' width='" << W - L - R << "' height='" << H - T - B
    << "' fill='#fff' stroke='#888'/>\n";
  for (double t : logX ? logTicks(x0, x1) : linearTicks(x0, x1))
    s << "<line x1='" << X(t) << "' x2='" << X(t) << "' y1='" << T << "' y2='" << H - B << "' class='grid'/><text x='"
      << X(t) << "' y='" << H - B + 22 << "' text-anchor='middle'>" << num(t) << "</text>\n";
  for (double t : ya.ticks())
    s << "<line x1='" << L << "' x2='" << W - R << "' y1='" << Y(t) << "' y2='" << Y(t) << "' class='grid'/><text x='"
      << L - 8 << "' y='" << Y(t) + 5 << "' text-anchor='end'>" << num(t) << "</text>\n";
  s << "<text x='" << (L + W - R) / 2 << "' y='" << H - 20 << "' text-anchor='middle' class='axis'>time per frame, ms"
    << (logX ? " (log scale)" : "") << " — median, " << xmlEscaped(r.timer) << " timer</text>\n";
  s << "<text transform='translate(22," << (T + H - B) / 2
    << ") rotate(-90)' text-anchor='middle' class='axis'>wrong pixels, %" << (ya.log ? " (log scale)" : "")
    << "</text>\n";

  // Pareto front (lower error and lower time are both better).
  std::vector<size_t> order(es.size());
  for (size_t i = 0; i < es.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return es[a].msMedian != es[b].msMedian ? es[a].msMedian < es[b].msMedian
                                            : es[a].error.wrongPixelPct < es[b].error.wrongPixelPct;
  });
  std::vector<size_t> front;
  double best = 1e30;
  for (size_t i : order)
    if (es[i].error.wrongPixelPct < best) {
      front.push_back(i);
      best = es[i].error.wrongPixelPct;
    }
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
    double tw = (onFront ? 8.4 : 7.8) * text.size(), th = 16;
    const double cand[][2] = {{16, 5},  {-16 - tw, 5},   {-tw / 2, -16}, {-tw / 2, 28}, {14, -12},
                              {14, 22}, {-14 - tw, -12}, {-14 - tw, 22}, {14, 36},      {14, -26}};
    double lx = px + 14, ly = py + 5;
    int bestCost = 1 << 30;
    for (const auto& c : cand) {
      Box b{px + c[0], py + c[1] - th + 4, px + c[0] + tw, py + c[1] + 4};
      int cost = (b.x0 > L && b.x1 < W - R && b.y0 > T && b.y1 < H - B) ? 0 : 100;
      for (const auto& o : taken) cost += b.hits(o) ? 1 : 0;
      if (cost < bestCost) {
        bestCost = cost;
        lx = px + c[0], ly = py + c[1];
      }
    }
    taken.push_back({lx, ly - th + 4, lx + tw, ly + 4});
    s << "<text x='" << lx << "' y='" << ly << "' class='pt" << (onFront ? " front" : "") << "'>" << xmlEscaped(text)
      << "</text>\n";
  }
  s << "<g transform='translate(" << W - R - 272 << "," << T + 10
    << ")'><rect x='-8' y='-6' width='254' "
       "height='50' fill='#fff' stroke='#ccc'/><circle cx='10' cy='10' r='9' class='ring'/><line x1='26' x2='50' "
       "y1='10' y2='10' class='pareto'/><text x='58' y='15' class='note'>Pareto front: nothing is</text>"
       "<text x='58' y='35' class='note'>both faster and more exact</text></g>\n";
  s << "</svg>\n";
  return s.str();
}

std::string convergenceSvg(const BenchResult& r, const std::vector<Style>& styles) {
  size_t longest = 0;
  for (const auto& e : r.entries) longest = std::max(longest, legendLabel(e).size());
  const double W = 960, H = std::max(420.0, 120.0 + 22.0 * r.entries.size()), L = 80, T = 20, B = 60;
  const double R = std::clamp(76.0 + 7.6 * longest, 250.0, 480.0);
  int n = 1;
  double ymax = 0;
  for (const auto& e : r.entries) {
    n = std::max<int>(n, static_cast<int>(e.convergence.size()));
    for (double v : e.convergence) ymax = std::max(ymax, v);
  }
  std::vector<double> ys;
  for (const auto& e : r.entries) ys.insert(ys.end(), e.convergence.begin(), e.convergence.end());
  ErrorAxis ya(ys);
  (void)ymax;
  auto X = [&](double f) { return L + (n > 1 ? (f - 1) / (n - 1) : 0.5) * (W - L - R); };
  auto Y = [&](double v) { return H - B - ya.frac(v) * (H - T - B); };
  std::ostringstream s;
  s << "<svg viewBox='0 0 " << W << " " << H << "' class='chart' role='img' aria-label='error per frame'>\n";
  s << "<rect x='" << L << "' y='" << T << "' width='" << W - L - R << "' height='" << H - T - B
    << "' fill='#fff' stroke='#888'/>\n";
  for (double t : linearTicks(1, n))
    if (t >= 1 && std::abs(t - std::round(t)) < 1e-9)
      s << "<line x1='" << X(t) << "' x2='" << X(t) << "' y1='" << T << "' y2='" << H - B << "' class='grid'/><text x='"
        << X(t) << "' y='" << H - B + 22 << "' text-anchor='middle'>" << num(t) << "</text>\n";
  for (double t : ya.ticks())
    s << "<line x1='" << L << "' x2='" << W - R << "' y1='" << Y(t) << "' y2='" << Y(t) << "' class='grid'/><text x='"
      << L - 8 << "' y='" << Y(t) + 5 << "' text-anchor='end'>" << num(t) << "</text>\n";
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

const char* kCss = R"(
body{font:16px/1.45 system-ui,-apple-system,"Segoe UI",Roboto,sans-serif;color:#222;max-width:1000px;margin:24px auto;padding:0 16px}
h1{font-size:28px;margin:0 0 4px}h2{font-size:22px;margin:32px 0 8px;border-bottom:2px solid #ddd}
h3{font-size:17px;margin:18px 0 6px}.meta{color:#555;font-size:14px}code{font-size:13px;background:#f3f3f3;padding:1px 4px;word-break:break-all}
.chart{width:100%;height:auto;font-size:14px;font-family:inherit}.chart .grid{stroke:#e3e3e3}.chart .axis{font-size:16px;font-weight:600}
.chart .pt{font-size:13px}.chart .pt.front{font-weight:700}.chart .note{font-size:14px}
.chart .pareto{fill:none;stroke:#333;stroke-width:1.5;stroke-dasharray:5 4}.chart .ring{fill:none;stroke:#333;stroke-width:2}
table{border-collapse:collapse;font-size:14px;width:100%}th,td{padding:4px 8px;border-bottom:1px solid #ddd;text-align:right}
th{background:#f3f3f3;cursor:pointer;user-select:none;position:sticky;top:0}th:first-child,td:first-child{text-align:left}
.strip{display:grid;grid-template-columns:1fr 1fr 1fr;gap:6px}.strip figure{margin:0}.strip img{width:100%;display:block;image-rendering:pixelated;border:1px solid #ccc}
.strip figcaption{font-size:13px;color:#555}.swatch{display:inline-block;width:12px;height:12px;border:1px solid #888;vertical-align:-1px;margin:0 3px 0 10px}
.caption{font-size:14px;color:#444;margin:4px 0 0}
)";

const char* kSortScript = R"(<script>
for (const th of document.querySelectorAll('#results th')) th.addEventListener('click', () => {
  const tb = th.closest('table').tBodies[0], i = th.cellIndex, asc = th.dataset.asc !== '1';
  th.dataset.asc = asc ? '1' : '0';
  const key = td => { const v = parseFloat(td.dataset.v ?? td.textContent); return isNaN(v) ? td.textContent : v; };
  [...tb.rows].sort((a, b) => { const x = key(a.cells[i]), y = key(b.cells[i]);
    return (x < y ? -1 : x > y ? 1 : 0) * (asc ? 1 : -1); }).forEach(r => tb.appendChild(r));
});
</script>)";

std::string fileSafe(const std::string& s) {
  std::string o;
  for (char c : s) o += std::isalnum(static_cast<unsigned char>(c)) ? c : '-';
  return o;
}

// The chart as a file of its own (docs embed it): its namespace and the page's chart styles.
std::string standaloneSvg(const std::string& svg) {
  const size_t open = svg.find("<svg ");
  const size_t close = svg.find('>', open);
  if (open == std::string::npos || close == std::string::npos) return svg;
  return svg.substr(0, open) + "<svg xmlns='http://www.w3.org/2000/svg' " + svg.substr(open + 5, close - open - 5) +
         " font-family='system-ui,sans-serif' font-size='14'>\n<style>.grid{stroke:#e3e3e3}.axis{font-size:16px;"
         "font-weight:600}</style>\n" +
         svg.substr(close + 1);
}

// The sortable table: one row per entry, and what the columns mean.
std::string resultsTable(const BenchResult& r) {
  const bool path = !r.options.path.empty();
  const std::string base = r.entries.empty() ? std::string() : xmlEscaped(r.entries.front().label);
  std::ostringstream s;
  s << "<h2>Results</h2>\n<table "
       "id='results'><thead><tr><th>entry</th><th>ms/frame<br>median</th><th>ms/frame<br>p95</th>"
       "<th>× entry 1<br>(p25–p75)</th><th>wrong<br>%</th><th>image<br>wrong %</th><th>false shadow<br>%</th>"
       "<th>false light<br>%</th><th>RMSE</th>"
    << (path ? "<th>flicker<br>excess</th><th>world<br>flicker</th>" : "")
    << "<th>NaN/Inf<br>pixels</th></tr></thead><tbody>\n";
  for (const auto& e : r.entries) {
    s << "<tr><td>" << xmlEscaped(e.label) << "</td><td>" << fixed(e.msMedian, 2) << "</td><td>" << fixed(e.msP95, 2)
      << "</td><td data-v='" << e.msRatio << "'>" << fixed(e.msRatio, 2) << " (" << fixed(e.msRatioP25, 2) << "–"
      << fixed(e.msRatioP75, 2) << ")</td><td>" << fixed(e.error.wrongPixelPct, 2) << "</td><td>"
      << fixed(e.image.imageWrongPct, 2) << "</td><td>" << fixed(e.error.falseShadowPct, 2) << "</td><td>"
      << fixed(e.error.falseLightPct, 2) << "</td><td>" << fixed(e.error.rmse, 4) << "</td>";
    if (path) s << "<td>" << fixed(e.flicker, 4) << "</td><td>" << fixed(e.worldFlicker, 5) << "</td>";
    s << "<td>" << e.nonfinite << "</td></tr>\n";
  }
  s << "</tbody></table>\n<p class='caption'>Click a column header to sort. <b>× entry 1</b>: the entries are "
       "rendered in turn at each frame index, and this is the median over frames of the entry's frame time over "
       "that of entry 1 ("
    << base
    << ") at the same frame, with its quartiles: compare costs by this, it holds from run to run where the "
       "ms columns drift with the machine. <b>Image wrong</b>: pixels of the shaded colour image whose R, G or "
       "B differs by more than 30/255 from the same shading with the reference's visibility (Scherzer et al.'s "
       "figure 3); a visibility error the shading hides (grazing light, dark albedo) is wrong but not image "
       "wrong. Per-pass medians are in the JSON (<code>passes</code>) and all columns in <a "
       "href='results.csv'>results.csv</a>."
    << (path ? " Flicker excess: mean absolute frame-to-frame visibility change of the technique minus that of "
               "the reference along the path."
             : "")
    << "</p>\n";
  return s.str();
}

}  // namespace

void writeBenchReport(const BenchResult& r, const std::string& dir) {
  std::filesystem::create_directories(dir);
  writeBenchCsv(r, dir + "/results.csv");
  const ReferenceImage& ref = r.lastReference;
  const int w = r.options.width, h = r.options.height;
  writePng(dir + "/reference.png", w, h, visibilityToRgba(ref.visibility));
  std::vector<std::string> names;
  for (size_t i = 0; i < r.entries.size(); ++i) {
    const auto& e = r.entries[i];
    char prefix[32];
    std::snprintf(prefix, sizeof prefix, "%02zu-", i + 1);
    std::string base = prefix + fileSafe(shortLabel(e));
    names.push_back(base);
    writePng(dir + "/" + base + "-visibility.png", w, h, visibilityToRgba(e.lastVisibility));
    writePng(dir + "/" + base + "-error.png", w, h,
             errorImage(e.lastVisibility.data(), ref.visibility.data(), ref.valid.data(), e.lastVisibility.size()));
    if (!e.changeMap.empty() && e.changeMap.size() == r.referenceChangeMap.size())
      writePng(dir + "/" + base + "-flicker.png", w, h,
               flickerImage(e.changeMap, r.referenceChangeMap, r.pathValid.data(), kFlickerFullScale));
  }
  auto styles = entryStyles(r);
  const bool path = !r.options.path.empty();

  std::ostringstream s;
  s << "<!doctype html>\n<html lang='en'><head><meta charset='utf-8'><title>shadowlab bench: "
    << xmlEscaped(r.sceneName) << "</title>\n<style>" << kCss << "</style></head><body>\n";
  s << "<h1>Shadow error against frame time — scene <em>" << xmlEscaped(r.sceneName) << "</em></h1>\n";
  s << "<p class='meta'>" << w << "×" << h << " pixels, "
    << (path ? "camera path <b>" + xmlEscaped(r.options.path) + "</b>"
             : "camera <b>" + xmlEscaped(r.options.camera) + "</b>")
    << ", " << r.options.frames << " measured frames after " << r.options.warmup
    << " warm-up frames, the entries rendered in turn at each frame. Renderer " << xmlEscaped(r.renderer)
    << ", timer <b>" << xmlEscaped(r.timer) << "</b>"
    << (r.timer == "cpu-fence" ? " (glFinish + steady clock around each pass)" : " (GL_TIME_ELAPSED queries)") << ", "
    << r.cores << " cores" << (r.cpu.empty() ? "" : " (" + xmlEscaped(r.cpu) + ")") << ", " << xmlEscaped(r.date)
    << ". Reference: Embree ray-traced visibility of the same G-buffer, " << r.referenceSamples
    << " light sample(s) per pixel.<br>Command: <code>" << xmlEscaped(r.options.commandLine) << "</code><br>Source: "
    << (r.commit.empty() ? std::string("not a git checkout") : "commit <code>" + xmlEscaped(r.commit) + "</code>")
    << (r.dirty ? " with uncommitted changes" : "") << ", build type " << xmlEscaped(r.buildType) << "</p>\n";

  if (!r.shaderErrors.empty()) {
    s << "<p style='border:2px solid #c00;padding:8px;color:#900'><b>Shader errors during this run</b>: entries "
         "using the broken shader measured nothing meaningful.<br><code>";
    for (const auto& e : r.shaderErrors) s << xmlEscaped(e.substr(0, 300)) << "<br>";
    s << "</code></p>\n";
  }
  s << "<h2>Error against time</h2>\n" << scatterSvg(r, styles);
  std::string sweepKeys;
  for (const auto& sw : r.options.sweeps) sweepKeys += (sweepKeys.empty() ? "" : ", ") + sw.substr(0, sw.find('='));
  s << "<p class='caption'>Each point is one technique at one sweep setting, labelled with its technique"
    << (sweepKeys.empty() ? std::string() : " and " + xmlEscaped(sweepKeys))
    << ". "
       "Lower left is better. Wrong pixels are those whose visibility differs from the ray-traced reference by "
       "more than 30/255 (Scherzer et al. 2007), in percent of pixels covered by geometry, in the last frame.</p>\n";

  const std::string convergence = convergenceSvg(r, styles);
  {
    std::ofstream svg(dir + "/convergence.svg");
    if (!svg) throw std::runtime_error(dir + "/convergence.svg: cannot write");
    svg << standaloneSvg(convergence);
  }
  s << "<h2>Convergence</h2>\n" << convergence;
  s << "<p class='caption'>Wrong pixels per measured frame, "
    << (path ? "each frame against its own reference (the camera moves)" : "against one reference (still camera)")
    << ". Techniques without temporal accumulation are flat.</p>\n";

  s << resultsTable(r);

  s << "<h2>Images (last frame)</h2>\n<p class='caption'>Visibility (white = lit) of the technique, the reference, "
       "and the <b>error view</b>: grey = agrees (reference at half brightness),<span class='swatch' "
       "style='background:#e67800'></span>orange = false shadow,<span class='swatch' style='background:#2878ff'>"
       "</span>blue = false light (light leak),<span class='swatch' style='background:#f0f'></span>magenta = "
       "NaN/Inf, black = background."
    << (path ? " <b>Flicker map</b> (along the path): per pixel, the technique's mean frame-to-frame change minus "
               "the reference's; grey = as steady as the truth, yellow to white = flickers more (white at " +
                   fixed(kFlickerFullScale, 2) + " per frame), blue = steadier (edges that lag or blur)."
             : std::string())
    << "</p>\n";
  for (size_t i = 0; i < r.entries.size(); ++i) {
    const auto& e = r.entries[i];
    s << "<h3 id='e" << i + 1 << "'>" << xmlEscaped(e.label) << " — " << fixed(e.error.wrongPixelPct, 2) << " % wrong, "
      << fixed(e.image.imageWrongPct, 2) << " % image wrong, " << fixed(e.msMedian, 2)
      << " ms</h3>\n<div class='strip'><figure><img src='" << names[i]
      << "-visibility.png' alt='technique'><figcaption>" << xmlEscaped(e.technique)
      << "</figcaption></figure><figure><img src='reference.png' alt='reference'><figcaption>reference (ray "
         "traced)</figcaption></figure><figure><img src='"
      << names[i] << "-error.png' alt='error view'><figcaption>error view</figcaption></figure>";
    if (!e.changeMap.empty())
      s << "<figure><img src='" << names[i] << "-flicker.png' alt='flicker map'><figcaption>flicker map</figcaption>"
        << "</figure>";
    s << "</div>\n";
  }
  s << kSortScript << "\n</body></html>\n";
  std::ofstream f(dir + "/index.html");
  if (!f) throw std::runtime_error(dir + "/index.html: cannot write");
  f << s.str();
}

}  // namespace sl
