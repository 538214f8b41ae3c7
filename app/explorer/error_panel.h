// The live accuracy panel: each viewport's error against the ray-traced reference, traced on a
// worker thread while the camera rests, its cost per frame, the error-vs-time chart of the
// configurations tried this session, and the `error` debug view.
//
// The first half of this header is plain logic without GL or ImGui (rest detection, Pareto
// front, chart axes, per-viewport cost), tested in tests/explorer_error_panel_test.cpp.
#pragma once

#include "bench/reference_cache.h"
#include "metrics/metrics.h"
#include "part/frame_graph.h"
#include "scene/scene.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace sl {

class ParamSet;
class Renderer;
class Texture2D;
struct ExplorerState;
struct Technique;

// ---------------------------------------------------------------------------------------------
// Logic (no GL, no ImGui)

// Everything the reference of a frame depends on that can change while the window is open.
struct RestKey {
  Camera camera;
  int width = 0, height = 0;
  double time = 0.0;             // scene time; 0 for scenes without motion (time does not matter)
  uint64_t sceneGeneration = 0;  // bumped whenever the explorer replaces its scene
};

// What differs between two keys (for the panel's "why not measuring" line).
struct RestKeyChange {
  bool camera = false, size = false, time = false, scene = false;
  bool any() const { return camera || size || time || scene; }
};
// Camera compared with a tiny relative tolerance (a resting fly camera must count as resting
// even if its pose is recomputed with rounding differences).
RestKeyChange compareRestKeys(const RestKey& a, const RestKey& b);
bool sameRestKey(const RestKey& a, const RestKey& b);

// Counts how long the key has stayed the same.
class RestDetector {
 public:
  explicit RestDetector(double restSeconds = 0.3) : restSeconds_(restSeconds) {}
  // Feeds the key of the frame just drawn at time `now` (seconds); returns resting().
  bool update(const RestKey& key, double now);
  bool resting() const { return have_ && now_ - stillSince_ >= restSeconds_; }
  double stillSeconds() const { return have_ ? now_ - stillSince_ : 0.0; }
  const RestKeyChange& lastChange() const { return lastChange_; }  // of the latest change seen
  const RestKey& key() const { return key_; }

 private:
  double restSeconds_;
  bool have_ = false;
  RestKey key_;
  double stillSince_ = 0.0, now_ = 0.0;
  RestKeyChange lastChange_;
};

// One configuration measured this session.
struct ChartPoint {
  std::string config;  // technique label + parameters changed from its preset
  double ms = 0;       // per frame, own passes (see viewportFrameMs): median of msReadings
  double wrongPct = 0;
  int viewport = -1;  // viewport it was last measured in (0-based), for its colour
  double imageWrongPct = 0;
  std::vector<double> msReadings;                         // the ms of every measurement of this config, oldest first
  std::vector<double> wrongReadings, imageWrongReadings;  // the last kChartErrorReadings errors
};
constexpr size_t kChartReadingsKept = 64;
// Errors: a short window, so an accumulating technique's point follows its convergence within a
// few measurements while one flickering frame (or one view) does not move it.
constexpr size_t kChartErrorReadings = 5;
// Adds a point, or a reading to the point with the same config string: viewport from the latest
// measurement, error and image error the median of the last kChartErrorReadings, ms the median
// of the last kChartReadingsKept readings, so a point does not wander with each reading's noise.
void recordChartPoint(std::vector<ChartPoint>& points, const ChartPoint& reading);
// Indices of the points no other point beats in both time and error, by increasing ms.
// (A point is dominated when another is at most as slow and as wrong, and better in one.)
std::vector<size_t> paretoFront(const std::vector<ChartPoint>& points);

// A chart axis: linear, or logarithmic when the values span a wide range.
struct ChartAxis {
  double lo = 0, hi = 1;
  bool log = false;
  double toUnit(double v) const;      // 0 at lo, 1 at hi (clamped values outside)
  std::vector<double> ticks() const;  // "nice" values inside [lo, hi]
};
// Log scale when hi/lo exceeds `logRatio` (values below `floor` are drawn at `floor`); the
// range is padded and rounded outward to tick values.
ChartAxis chooseChartAxis(double minValue, double maxValue, double floor, double logRatio = 20.0);
std::string formatTick(double v);
// The chart as a standalone SVG (axes with ticks, the Pareto front dashed, one labelled point
// per configuration) and its points as CSV rows, for slides and spreadsheets.
std::string chartPointsSvg(const std::vector<ChartPoint>& points);
std::string chartPointsCsv(const std::vector<ChartPoint>& points);
// A CSV field: quoted when it holds a comma, quote or newline.
std::string csvField(const std::string& text);
// The accuracy CSV's rows for the other lights of a scene of several (one per shadowed light,
// "V light K" in the viewport column, the image column empty: the colour sums every light and
// is on the viewport's own row).
std::string otherLightsCsvRows(int viewport, const std::string& config,
                               const std::vector<LightVisibilityError>& lights);

// Cost of viewport v in one frame: its own passes only (names ending in "[v]"; debug views
// "view.*" excluded: they are display, not the technique). The shared "gbuffer" pass is kept
// apart: techniques shade forward and do not read it, it runs only for debug views and the
// reference readback. ownMs is negative when no pass of that viewport was timed.
struct ViewportCost {
  double ownMs = -1, gbufferMs = 0;
};
ViewportCost viewportFrameMs(const std::vector<PassTiming>& passes, int viewportIndex);

// "key=value, key=value" for the parameters that differ from `reference` (the preset's values).
std::string paramSummary(const ParamSet& current, const ParamSet& reference);
// Label plus the changed parameters: the identity of a point in the chart.
std::string configString(const Technique& technique);

// Frames the accuracy panel's ms column is the median of.
constexpr size_t kCostFrames = 30;

// Median of a small window of samples, for per-pass times that spike on shader builds.
class MedianWindow {
 public:
  explicit MedianWindow(size_t size = 15) : size_(size) {}
  void add(double v);
  void clear() { values_.clear(); }
  size_t count() const { return values_.size(); }
  double median() const;  // -1 when empty

 private:
  size_t size_;
  std::vector<double> values_;  // oldest first
};

// ---------------------------------------------------------------------------------------------
// The panel (GL thread only, except the worker it owns)

class ErrorPanel {
 public:
  static constexpr const char* kViewName = "error";

  ErrorPanel();
  ~ErrorPanel();  // cancels and joins the worker
  ErrorPanel(const ErrorPanel&) = delete;
  ErrorPanel& operator=(const ErrorPanel&) = delete;

  // After the viewports rendered this frame (`rendered` false when the frame failed): rest
  // detection, G-buffer readback and worker start/cancel, per-viewport metrics and the error view.
  void afterRender(ExplorerState& state, Renderer& renderer, int width, int height, bool rendered);
  // The next frame must keep its G-buffer: the camera rests and this view has no reference yet.
  // (Techniques shade forward, so the G-buffer is otherwise skipped to keep the window fast.)
  bool wantsGBuffer() const { return rest_.resting() && currentRef_ == 0 && !active_; }
  // The "Accuracy vs ray-traced truth" section of the side panel.
  void drawPanel(ExplorerState& state);
  // Must be called before the explorer replaces (destroys) its scene: the worker reads it while
  // building its BVH. Joins the worker and forgets references of the old scene.
  void beforeSceneChange();

  // The `error` view of viewport slot `slot` for the frame on screen, or null (then
  // errorViewStatus says why).
  const Texture2D* errorTexture(int slot) const;
  std::string errorViewStatus() const;
  // Exports (error_panel_export.cpp): the accuracy table of the shown viewports, then every
  // configuration of the chart, as CSV; the chart as SVG.
  std::string accuracyCsv(const ExplorerState& state) const;
  std::string chartSvg() const { return chartPointsSvg(points_); }

  struct Job;  // a reference being traced (defined in the .cpp)

 private:
  struct Reference {
    RestKey key;
    std::vector<float> visibility;
    std::vector<std::vector<float>> otherVisibility;  // Scene::otherLights' (image error)
    std::vector<uint8_t> valid;
    uint64_t id = 0;
    double traceMs = 0, buildMs = 0;
  };
  struct ViewportAccuracy {
    std::string config;  // of the last measurement
    bool haveMetrics = false;
    ErrorMetrics metrics;
    ImageErrorMetrics image;  // colour vs the same shading with the reference's visibility
    // A scene of several lights: each other light's visibility against its own reference (the
    // columns above are the first light's; `image` sums them all).
    std::vector<LightVisibilityError> otherLights;
    ViewportCost cost;  // medians at the last measurement
    double measuredAt = -1e9;
    uint64_t referenceId = 0;
    std::string timedConfig;  // config the timing window belongs to
    MedianWindow ownMs{kCostFrames}, gbufferMs{kCostFrames};
    std::unique_ptr<Texture2D> errorTexture;
    uint64_t errorTextureReference = 0;  // reference the texture was computed against (0 = stale)
  };

  // What the panel shows of the active trace (the worker's state stays in error_panel.cpp).
  struct JobProgress {
    float fraction = 0;  // rows traced / rows
    bool building = false;
    double seconds = 0;
    int threads = 0, samples = 0, width = 0, height = 0;
  };
  JobProgress activeProgress() const;  // requires active_

  const Reference* findReference(const RestKey& key) const;
  const Reference* currentReference() const;
  void pollJobs();
  void cancelActive();
  void joinAll();
  void startJob(ExplorerState& state, Renderer& renderer, const RestKey& key);
  void measure(ExplorerState& state, Renderer& renderer, const Reference& ref, int slot, bool wantImage);

  // drawPanel's parts (error_panel_draw.cpp).
  void drawStatus() const;
  void drawAccuracyTable(const ExplorerState& state) const;
  void drawAccuracyRow(int viewport) const;
  std::vector<std::string> shownConfigs(const ExplorerState& state) const;
  void drawChart(const ExplorerState& state);

  RestDetector rest_;
  uint64_t sceneGeneration_ = 1;
  std::vector<Reference> references_;  // most recent last, a few kept (jumping between cameras)
  uint64_t nextReferenceId_ = 1;
  std::unique_ptr<Job> active_;
  std::vector<std::unique_ptr<Job>> retiring_;  // cancelled, finishing their current chunk
  std::string jobError_;
  RestKey failedKey_;  // a failed trace is not retried for the same view
  bool haveFailed_ = false;
  ViewportAccuracy viewports_[4];
  std::vector<ChartPoint> points_;
  bool sceneMoves_ = false;
  bool rendered_ = false;
  bool timing_ = true;
  uint64_t currentRef_ = 0;  // id of the reference of the frame on screen, 0 = none
  double now_ = 0;
};

}  // namespace sl
