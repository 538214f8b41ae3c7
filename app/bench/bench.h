// `shadowlab bench`: every technique x sweep point with a viewport of its own on the same camera
// (or camera path), the entries rendered in turn at each frame index (A B A B ...), timed with
// the renderer's pass timers and compared with the ray-traced reference. Results go to JSON, and
// optionally to a self-contained HTML report.
#pragma once

#include "bench/reference_cache.h"

#include <nlohmann/json.hpp>

#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace sl {

struct BenchOptions {
  std::string scene = "basic";
  std::vector<std::string> techniques;  // preset ids
  std::vector<std::string> sets;        // "key=value", applied to every technique that has the key
  std::vector<std::string> sweeps;      // "key=v1,v2,...": cartesian product over all of them
  std::string camera;                   // camera name ("" = the scene's first), or
  std::string path;                     // a camera path name: frames advance along it at 30 fps
  int frames = 10;
  int warmup = 3;
  // Frames of coherent camera motion (a rotation about the target, from approachDeg to 0)
  // rendered before the measured frames without a cut: the measured frames then start with a
  // filled history, as in the left graph of Scherzer et al.'s figure 3. 0 = empty history.
  int approach = 0;
  float approachDeg = 20.0f;
  int width = 640, height = 360;
  int samples = 64;       // reference light samples
  bool useCache = true;   // reference disk cache
  double time = 0.0;      // scene time (start time with --path)
  std::string shaderDir;  // "" = defaultShaderDir()
  std::string commandLine;
};

// One technique with one sweep point, before running.
struct BenchPlanEntry {
  Technique technique;
  std::vector<std::pair<std::string, std::string>> sweepPoint;  // key, value as given
};

struct PassMs {
  std::string name;
  double ms = 0;  // median over the measured frames
};

struct BenchEntry {
  std::string technique;                                    // preset id
  std::string label;                                        // "pcf shadowmap.size=1024"
  std::vector<std::pair<std::string, std::string>> params;  // every resolved value
  std::vector<std::pair<std::string, std::string>> sweepPoint;
  int frames = 0;
  std::string timer;
  double msMedian = 0, msP95 = 0;
  std::vector<double> frameMs;  // every measured frame, in order (the ratios pair them by index)
  // Cost relative to entry 0 (the first of the plan): median and quartiles over the measured
  // frames of (this entry's frame ms / entry 0's at the same frame index). The entries render
  // each frame index back to back, so machine noise lands on both sides of the ratio. 1 for entry 0.
  double msRatio = 1, msRatioP25 = 1, msRatioP75 = 1;
  std::vector<PassMs> passes;
  ErrorMetrics error;       // last frame vs its reference
  ImageErrorMetrics image;  // last frame's colour vs the same shading with the reference's visibility
  // A scene of several lights: `error` is the first light's; these are the others' (one per
  // Scene::otherLights entry, against the reference traced toward that light; empty `shadowed`
  // where the technique made no maps for it: unshadowed in the file or beyond lights.shadowed).
  using LightError = LightVisibilityError;
  std::vector<LightError> otherLights;
  std::vector<double> convergence;  // wrong_pixel_pct per measured frame
  bool hasFlicker = false;
  double flicker = 0, flickerTechnique = 0, flickerReference = 0;
  // World-space flicker along a path: the path's first view shaded at every frame with the maps
  // fitted to that frame's camera (FrameInput::fitCamera, the scene time held), mean per pixel
  // of |frame-to-frame change|. The truth at a fixed world point does not change, so this is the
  // shimmer of the map alone, free of the screen-space metric's floor (an edge that the moving
  // pixel grid crosses at other frames than the true edge).
  double worldFlicker = 0;
  long long nonfinite = 0;            // NaN/Inf visibility pixels in the last frame
  long long shadowTexels = 0;         // Viewport::shadowTexels after the last frame
  std::string status;                 // the parts' status lines after the last frame
  std::vector<float> lastVisibility;  // for the report's images
  std::vector<float> changeMap;       // per pixel mean |frame-to-frame change| along a path (report)
};

struct BenchResult {
  BenchOptions options;
  std::string sceneName, renderer, timer, date, cpu;
  std::string commit, buildType;  // provenance: git commit of the source ("" outside a checkout), CMAKE_BUILD_TYPE
  bool dirty = false;             // tracked files differed from that commit
  unsigned cores = 0;
  int referenceSamples = 0;
  int referencesTraced = 0, referencesCached = 0;
  double referenceTraceMs = 0;  // total, over the references traced in this run
  double referenceFlicker = 0;
  std::vector<float> referenceChangeMap;  // per pixel, along a path
  std::vector<uint8_t> pathValid;         // pixels covered in every frame of the path (flicker is over these)
  std::vector<uint8_t> worldValid;        // pixels covered in the path's first frame (world-space flicker)
  ReferenceImage lastReference;           // reference of the last frame (the one `error` compares with)
  std::vector<BenchEntry> entries;
  std::vector<std::string> shaderErrors;  // any: the affected entries measured a broken shader
};

// Validates techniques, --set and --sweep (throws ArgError/ParamError with a clear message:
// an unknown key, a key no technique has, a value out of range) and lists the entries.
std::vector<BenchPlanEntry> planBench(const BenchOptions& options);
// Runs the plan headless; progress lines go to `log`.
BenchResult runBench(const BenchOptions& options, std::ostream& log);

nlohmann::json benchToJson(const BenchResult& result);
void writeBenchCsv(const BenchResult& result, const std::string& file);
// index.html (inline CSS + SVG), results.csv and per-entry PNGs in `dir` (created).
void writeBenchReport(const BenchResult& result, const std::string& dir);

}  // namespace sl
