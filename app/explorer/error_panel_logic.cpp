// The accuracy panel's logic without GL or ImGui (rest detection, chart, costs): unit-tested.
#include "explorer/error_panel.h"

#include "bench/reference_cache.h"
#include "explorer/explorer_state.h"
#include "reference/reference.h"
#include "render/renderer.h"
#include "technique.h"

#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sl {

// ---------------------------------------------------------------------------------------------
// Logic

namespace {

bool nearlyEqual(float a, float b) { return std::abs(a - b) <= 1e-6f * std::max({1.0f, std::abs(a), std::abs(b)}); }
bool nearlyEqual(const glm::vec3& a, const glm::vec3& b) {
  return nearlyEqual(a.x, b.x) && nearlyEqual(a.y, b.y) && nearlyEqual(a.z, b.z);
}

}  // namespace

RestKeyChange compareRestKeys(const RestKey& a, const RestKey& b) {
  RestKeyChange c;
  const Camera &p = a.camera, &q = b.camera;
  c.camera = !nearlyEqual(p.position, q.position) || !nearlyEqual(p.target, q.target) || !nearlyEqual(p.up, q.up) ||
             !nearlyEqual(p.fovDeg, q.fovDeg) || !nearlyEqual(p.nearPlane, q.nearPlane) ||
             !nearlyEqual(p.farPlane, q.farPlane);
  c.size = a.width != b.width || a.height != b.height;
  c.time = a.time != b.time;
  c.scene = a.sceneGeneration != b.sceneGeneration;
  return c;
}

bool sameRestKey(const RestKey& a, const RestKey& b) { return !compareRestKeys(a, b).any(); }

bool RestDetector::update(const RestKey& key, double now) {
  now_ = now;
  if (!have_) {
    have_ = true;
    key_ = key;
    stillSince_ = now;
    lastChange_ = RestKeyChange{};
    lastChange_.scene = true;
    return resting();
  }
  const RestKeyChange change = compareRestKeys(key_, key);
  if (change.any()) {
    lastChange_ = change;
    stillSince_ = now;
  }
  key_ = key;
  return resting();
}

namespace {

// Appends v, drops the oldest beyond `keep`, returns the median (mean of the middle two).
double pushAndMedian(std::vector<double>& readings, double v, size_t keep) {
  readings.push_back(v);
  if (readings.size() > keep) readings.erase(readings.begin(), readings.end() - long(keep));
  std::vector<double> sorted = readings;
  std::sort(sorted.begin(), sorted.end());
  const size_t n = sorted.size();
  return n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
}

}  // namespace

void recordChartPoint(std::vector<ChartPoint>& points, const ChartPoint& reading) {
  auto it = std::find_if(points.begin(), points.end(), [&](const ChartPoint& p) { return p.config == reading.config; });
  ChartPoint point = reading;
  point.msReadings.clear();
  point.wrongReadings.clear();
  point.imageWrongReadings.clear();
  if (it != points.end()) {
    point.msReadings = std::move(it->msReadings);
    point.wrongReadings = std::move(it->wrongReadings);
    point.imageWrongReadings = std::move(it->imageWrongReadings);
  }
  point.ms = pushAndMedian(point.msReadings, reading.ms, kChartReadingsKept);
  point.wrongPct = pushAndMedian(point.wrongReadings, reading.wrongPct, kChartErrorReadings);
  // The image error is NaN when it could not be measured: such a reading does not vote.
  if (std::isfinite(reading.imageWrongPct))
    point.imageWrongPct = pushAndMedian(point.imageWrongReadings, reading.imageWrongPct, kChartErrorReadings);
  else if (it != points.end())
    point.imageWrongPct = it->imageWrongPct;
  if (it != points.end())
    *it = std::move(point);
  else
    points.push_back(std::move(point));
}

std::vector<size_t> paretoFront(const std::vector<ChartPoint>& points) {
  std::vector<size_t> order(points.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (points[a].ms != points[b].ms) return points[a].ms < points[b].ms;
    return points[a].wrongPct < points[b].wrongPct;
  });
  std::vector<size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i : order) {
    // Sorted by time, then error: a point is on the front when it is strictly less wrong than
    // every point at least as fast.
    if (points[i].wrongPct < best) {
      front.push_back(i);
      best = points[i].wrongPct;
    }
  }
  return front;
}

double ChartAxis::toUnit(double v) const {
  double t;
  if (log) {
    v = std::max(v, lo);
    t = (std::log10(v) - std::log10(lo)) / std::max(1e-12, std::log10(hi) - std::log10(lo));
  } else {
    t = (v - lo) / std::max(1e-12, hi - lo);
  }
  return std::clamp(t, 0.0, 1.0);
}

namespace {

// Largest "nice" step (1, 2, 5 x 10^k) giving at most `maxTicks` intervals over `span`.
double niceStep(double span, int maxTicks) {
  const double raw = span / std::max(1, maxTicks);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10.0 * p;
}

}  // namespace

std::vector<double> ChartAxis::ticks() const {
  std::vector<double> t;
  if (log) {
    const int d0 = int(std::floor(std::log10(lo) + 1e-9)), d1 = int(std::ceil(std::log10(hi) - 1e-9));
    const bool fewDecades = d1 - d0 <= 2;
    for (int d = d0; d <= d1; ++d) {
      for (double m : {1.0, 2.0, 5.0}) {
        if (m != 1.0 && !fewDecades) continue;
        const double v = m * std::pow(10.0, d);
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) t.push_back(v);
      }
    }
    return t;
  }
  const double step = niceStep(hi - lo, 5);
  for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + step * 1e-9; v += step)
    t.push_back(std::abs(v) < step * 1e-9 ? 0.0 : v);
  return t;
}

ChartAxis chooseChartAxis(double minValue, double maxValue, double floor, double logRatio) {
  ChartAxis a;
  if (!(minValue <= maxValue)) minValue = maxValue = 0;  // no points / NaN
  const double lo = std::max(minValue, floor), hi = std::max(maxValue, floor);
  if (hi / lo > logRatio) {
    a.log = true;
    a.lo = std::pow(10.0, std::floor(std::log10(lo)));
    a.hi = std::pow(10.0, std::ceil(std::log10(hi)));
    if (a.hi <= a.lo) a.hi = a.lo * 10.0;
    return a;
  }
  // Linear from zero: distances to the origin then read as ratios, which is what one compares.
  double top = maxValue > 0 ? maxValue * 1.1 : 1.0;
  const double step = niceStep(top, 5);
  a.lo = 0;
  a.hi = std::ceil(top / step - 1e-9) * step;
  return a;
}

std::string formatTick(double v) {
  char buf[32];
  const double a = std::abs(v);
  if (a == 0)
    return "0";
  else if (a >= 100)
    std::snprintf(buf, sizeof buf, "%.0f", v);
  else if (a >= 1)
    std::snprintf(buf, sizeof buf, "%g", std::round(v * 10) / 10);
  else
    std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

ViewportCost viewportFrameMs(const std::vector<PassTiming>& passes, int viewportIndex) {
  ViewportCost c;
  const std::string tag = "[" + std::to_string(viewportIndex) + "]";
  for (const PassTiming& p : passes) {
    if (p.name == "gbuffer") {
      c.gbufferMs += p.ms;
      continue;
    }
    const bool mine = p.name.size() > tag.size() && p.name.compare(p.name.size() - tag.size(), tag.size(), tag) == 0;
    if (!mine || p.name.rfind("view.", 0) == 0) continue;
    c.ownMs = std::max(c.ownMs, 0.0) + p.ms;
  }
  return c;
}

std::string paramSummary(const ParamSet& current, const ParamSet& reference) {
  std::string s;
  for (const ParamDecl& d : current.decls()) {
    const double v = current.get(d.key);
    if (reference.has(d.key) && reference.get(d.key) == v) continue;
    s += (s.empty() ? "" : ", ") + d.key + "=" + formatValue(d, v);
  }
  return s;
}

std::string configString(const Technique& technique) {
  std::string summary;
  try {
    summary = paramSummary(technique.params, makeTechnique(technique.presetId).params);
  } catch (const std::exception&) {
    summary = "?";
  }
  return technique.label() + (summary.empty() ? "" : " {" + summary + "}");
}

void MedianWindow::add(double v) {
  values_.push_back(v);
  if (values_.size() > size_) values_.erase(values_.begin());
}

double MedianWindow::median() const {
  if (values_.empty()) return -1;
  std::vector<double> v = values_;
  std::nth_element(v.begin(), v.begin() + long(v.size() / 2), v.end());
  return v[v.size() / 2];
}

}  // namespace sl
