// Running `shadowlab bench`; see bench.h and docs/benchmarks.md ("Timing method"). Every entry
// keeps its own viewport and the entries are rendered in turn at each frame index (A B A B ...),
// so a slow spell of the machine lands on all of them and the cost ratios hold from run to run.
#include "bench/bench.h"

#include "cli/args.h"
#include "gl/headless_context.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <thread>

namespace sl {

namespace {

// Linear interpolation between the closest ranks (q = 0.5: the median).
double quantile(std::vector<double> v, double q) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const size_t i = static_cast<size_t>(pos);
  const double t = pos - static_cast<double>(i);
  return i + 1 < v.size() ? v[i] * (1 - t) + v[i + 1] * t : v[i];
}
double median(std::vector<double> v) { return quantile(std::move(v), 0.5); }

// Nearest-rank 95th percentile.
double p95(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  size_t rank = static_cast<size_t>(std::ceil(0.95 * static_cast<double>(v.size())));
  return v[std::clamp<size_t>(rank, 1, v.size()) - 1];
}

std::string isoDateUtc() {
  std::time_t now = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buf;
}

std::string cpuModel() {
  std::ifstream f("/proc/cpuinfo");
  std::string line;
  while (std::getline(f, line))
    if (line.rfind("model name", 0) == 0) {
      auto c = line.find(':');
      if (c != std::string::npos) return line.substr(line.find_first_not_of(' ', c + 1));
    }
  return "";
}

// First line a shell command prints ("" when it fails): git, for the bench's provenance.
std::string firstLineOf(const std::string& command) {
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buf[256];
    if (fgets(buf, sizeof buf, pipe)) out = buf;
    pclose(pipe);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  return out;
}

// Which source the numbers came from: the commit of the source folder, whether its tracked files
// differed from it, and the build type the program was compiled with.
void recordProvenance(BenchResult& r) {
  const std::string git = "git -C '" + std::string(SHADOWLAB_SOURCE_DIR) + "' ";
  r.commit = firstLineOf(git + "rev-parse HEAD 2>/dev/null");
  r.dirty = !r.commit.empty() && !firstLineOf(git + "status --porcelain --untracked-files=no 2>/dev/null").empty();
  r.buildType = SHADOWLAB_BUILD_TYPE;
}

// The frames every entry renders: a still camera and time (convergence), or the path at 30 fps.
struct BenchFrames {
  Camera camera;
  const CameraPath* path = nullptr;
  std::vector<FrameInput> inputs;
  bool still() const { return path == nullptr; }
};

BenchFrames benchFrames(const BenchOptions& o, const Scene& scene) {
  BenchFrames fr;
  fr.camera = scene.cameras.front();
  if (!o.camera.empty()) {
    const Camera* c = scene.findCamera(o.camera);
    if (!c) throw ArgError("scene '" + scene.name + "' has no camera '" + o.camera + "'");
    fr.camera = *c;
  }
  if (!o.path.empty()) {
    fr.path = scene.findPath(o.path);
    if (!fr.path) throw ArgError("scene '" + scene.name + "' has no camera path '" + o.path + "'");
  }
  fr.inputs.resize(o.frames);
  for (int f = 0; f < o.frames; ++f) {
    FrameInput& in = fr.inputs[f];
    in.width = o.width;
    in.height = o.height;
    in.time = fr.path ? o.time + f / 30.0 : o.time;
    in.camera = fr.path ? fr.path->sample(static_cast<float>(o.time + f / 30.0), fr.camera) : fr.camera;
    in.cut = f == 0 && o.approach == 0;
  }
  return fr;
}

// Frame `a` of the coherent camera motion into the measured view (filled history, not timed):
// along the path itself when there is one, else a rotation about the target.
FrameInput approachFrame(const BenchOptions& o, const BenchFrames& fr, int a) {
  FrameInput in = fr.inputs.front();
  in.cut = a == 0;
  if (fr.path) {
    in.time = o.time - (o.approach - a) / 30.0;
    in.camera = fr.path->sample(static_cast<float>(in.time), fr.camera);
    return in;
  }
  const float angle = glm::radians(o.approachDeg) * static_cast<float>(o.approach - a) / static_cast<float>(o.approach);
  const glm::vec3 offset = in.camera.position - in.camera.target;
  in.camera.position =
      in.camera.target + glm::vec3(glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0, 1, 0)) * glm::vec4(offset, 0.0f));
  return in;
}

// References first (each draws its own G-buffer with a private viewport), for one frame when
// still, else per path frame; counts go to `r`.
std::vector<ReferenceImage> benchReferences(const BenchOptions& o, const Scene& scene, Renderer& renderer,
                                            const BenchFrames& fr, BenchResult& r, std::ostream& log) {
  ReferenceSettings rs;
  rs.samples = o.samples;
  rs.useCache = o.useCache;
  r.referenceSamples = scene.light.radius > 0 ? o.samples : 1;
  ReferenceCache cache(scene, rs);
  std::vector<ReferenceImage> refs;
  for (size_t f = 0; f < (fr.still() ? 1 : fr.inputs.size()); ++f) {
    refs.push_back(cache.forFrame(renderer, fr.inputs[f]));
    if (refs.back().cached) {
      ++r.referencesCached;
    } else {
      ++r.referencesTraced;
      r.referenceTraceMs += refs.back().traceMs;
    }
  }
  log << "bench: reference " << (fr.still() ? "frame" : "frames") << ": " << r.referencesTraced << " traced ("
      << static_cast<long long>(r.referenceTraceMs) << " ms), " << r.referencesCached << " cached\n";
  return refs;
}

// One entry while the plan runs: its own viewport for the whole run (all live at once, so that
// they can be rendered in turn) and its per-frame readings.
struct EntryRun {
  BenchEntry out;
  std::unique_ptr<Viewport> viewport;
  std::map<std::string, std::vector<double>> passMs;
  std::vector<std::string> passOrder;
  std::vector<std::vector<float>> frames;  // visibility per frame, along a path (flicker)
  // Along a path: the same technique shading the path's first view with maps fitted to each
  // frame's camera (world-space flicker), and its visibility per frame.
  std::unique_ptr<Viewport> worldViewport;
  std::vector<std::vector<float>> worldFrames;
};

// Frame f of the world-space flicker: the first frame's view and time, fitted to frame f's camera.
FrameInput worldFrame(const BenchFrames& fr, int f) {
  FrameInput in = fr.inputs.front();
  in.fitCamera = fr.inputs[f].camera;
  in.cut = f == 0;
  return in;
}

EntryRun startEntry(const BenchPlanEntry& p, int frames, bool withWorldFlicker) {
  EntryRun run;
  BenchEntry& out = run.out;
  out.technique = p.technique.presetId;
  out.label = p.technique.presetId;
  for (const auto& [k, v] : p.sweepPoint) out.label += " " + k + "=" + v;
  for (const auto& d : p.technique.params.decls())
    out.params.emplace_back(d.key, formatValue(d, p.technique.params.get(d.key)));
  out.sweepPoint = p.sweepPoint;
  out.frames = frames;
  run.viewport = std::make_unique<Viewport>(p.technique);
  if (withWorldFlicker) run.worldViewport = std::make_unique<Viewport>(p.technique);
  return run;
}

// Warm-up (shader builds, target allocation, llvmpipe's threads and JIT caches settle: the first
// entries are not penalised), then each entry forgets its history and approaches the view.
// Entry by entry at each frame index, like the measured frames.
void prepareEntries(Renderer& renderer, std::vector<EntryRun>& runs, const std::vector<BenchPlanEntry>& plan,
                    const BenchOptions& o, const BenchFrames& fr) {
  for (int w = 0; w < std::max(1, o.warmup); ++w)
    for (EntryRun& run : runs) {
      FrameInput in = fr.inputs.front();
      in.cut = w == 0;
      renderer.render(in, {run.viewport.get()});
    }
  for (size_t e = 0; e < runs.size(); ++e) runs[e].viewport->setTechnique(plan[e].technique);
  for (int a = 0; a < o.approach; ++a) {
    const FrameInput in = approachFrame(o, fr, a);
    for (EntryRun& run : runs) renderer.render(in, {run.viewport.get()});
  }
}

// After the entry rendered measured frame `f`: its timings, its error against the frame's reference.
void recordFrame(const Renderer& renderer, EntryRun& run, const ReferenceImage& ref, bool last, bool keepFrames) {
  const FrameStats& st = renderer.stats();
  run.out.frameMs.push_back(st.frameMs);
  run.out.timer = st.timer;
  for (const auto& pt : st.passes) {
    if (!run.passMs.count(pt.name)) run.passOrder.push_back(pt.name);
    run.passMs[pt.name].push_back(pt.ms);
  }
  std::vector<float> vis = viewportVisibility(*run.viewport);
  ErrorMetrics m = compareVisibility(vis.data(), ref.visibility.data(), ref.valid.data(), vis.size());
  run.out.convergence.push_back(m.wrongPixelPct);
  if (last) {
    run.out.error = m;
    run.out.nonfinite = 0;
    for (float v : vis) run.out.nonfinite += std::isfinite(v) ? 0 : 1;
    run.out.shadowTexels = run.viewport->shadowTexels();
    run.out.status = run.viewport->status();
    run.out.lastVisibility = vis;
  }
  if (keepFrames) run.frames.push_back(std::move(vis));
}

// Medians, the cost ratio to entry 0 frame by frame, flicker along a path.
void finishEntry(EntryRun& run, const EntryRun& base, const BenchResult& r, const std::vector<uint8_t>& commonValid) {
  BenchEntry& out = run.out;
  out.msMedian = median(out.frameMs);
  out.msP95 = p95(out.frameMs);
  for (const auto& name : run.passOrder) out.passes.push_back({name, median(run.passMs[name])});
  // Frame f of every entry ran back to back: the ratio at the same f sees the same machine.
  std::vector<double> ratios;
  const std::vector<double>& baseMs = base.out.frameMs;
  for (size_t f = 0; f < out.frameMs.size() && f < baseMs.size(); ++f)
    if (baseMs[f] > 0) ratios.push_back(out.frameMs[f] / baseMs[f]);
  out.msRatio = median(ratios);
  out.msRatioP25 = quantile(ratios, 0.25);
  out.msRatioP75 = quantile(ratios, 0.75);
  if (!run.frames.empty()) {
    out.hasFlicker = true;
    out.flickerTechnique = meanTemporalChange(run.frames, commonValid.data());
    out.changeMap = temporalChangeMap(run.frames, commonValid.data());
    out.flickerReference = r.referenceFlicker;
    out.flicker = flickerExcess(out.changeMap, r.referenceChangeMap, commonValid.data());
  }
  if (!run.worldFrames.empty()) out.worldFlicker = meanTemporalChange(run.worldFrames, r.worldValid.data());
}

}  // namespace

BenchResult runBench(const BenchOptions& o, std::ostream& log) {
  std::vector<BenchPlanEntry> plan = planBench(o);
  BenchResult r;
  r.options = o;
  r.date = isoDateUtc();
  r.cores = std::thread::hardware_concurrency();
  r.cpu = cpuModel();
  recordProvenance(r);

  Scene scene = loadScene(o.scene, defaultAssetsDir());
  r.sceneName = scene.name;
  const BenchFrames fr = benchFrames(o, scene);
  r.options.camera = fr.path ? "" : fr.camera.name;

  HeadlessContext context;
  ShaderLibrary shaders(o.shaderDir.empty() ? defaultShaderDir() : o.shaderDir);
  Renderer renderer(shaders);
  renderer.setScene(scene);
  renderer.timePasses = true;
  r.renderer = glRendererName();
  const std::vector<ReferenceImage> refs = benchReferences(o, scene, renderer, fr, r, log);
  // Measured frames time only what the technique needs: no G-buffer kept for readback.
  renderer.keepGBuffer = false;

  // Flicker is measured over pixels covered in every frame, for technique and reference alike.
  std::vector<uint8_t> commonValid = refs.front().valid;
  for (const auto& ref : refs)
    for (size_t i = 0; i < commonValid.size(); ++i) commonValid[i] &= ref.valid[i];
  if (!fr.still()) {
    std::vector<std::vector<float>> refFrames;
    for (const auto& ref : refs) refFrames.push_back(ref.visibility);
    r.referenceFlicker = meanTemporalChange(refFrames, commonValid.data());
    r.referenceChangeMap = temporalChangeMap(refFrames, commonValid.data());
    r.pathValid = commonValid;
  }
  r.lastReference = refs.back();

  std::vector<EntryRun> runs;
  if (!fr.still()) r.worldValid = refs.front().valid;
  for (const auto& p : plan) runs.push_back(startEntry(p, o.frames, !fr.still()));
  prepareEntries(renderer, runs, plan, o, fr);
  log << "bench: " << runs.size() << " entries x " << o.frames << " frames, rendered in turn at each frame\n";
  for (int f = 0; f < o.frames; ++f)
    for (EntryRun& run : runs) {
      renderer.render(fr.inputs[f], {run.viewport.get()});
      recordFrame(renderer, run, refs[fr.still() ? 0 : f], f + 1 == o.frames, !fr.still());
    }
  // World-space flicker after the measured frames, which it must not touch (the renderer's last
  // frame is what the next one's motion is relative to).
  for (int f = 0; f < o.frames; ++f)
    for (EntryRun& run : runs) {
      if (!run.worldViewport) continue;
      renderer.render(worldFrame(fr, f), {run.worldViewport.get()});
      run.worldFrames.push_back(viewportVisibility(*run.worldViewport));
    }

  // The last frame's colour against the same shading with the truth's visibility.
  for (size_t e = 0; e < runs.size(); ++e) {
    EntryRun& run = runs[e];
    finishEntry(run, runs.front(), r, commonValid);
    run.out.image = viewportImageError(renderer, fr.inputs.back(), *run.viewport, r.lastReference.visibility,
                                       r.lastReference.valid, r.lastReference.otherLights);
    run.out.otherLights = otherLightsVisibilityError(*run.viewport, r.lastReference.otherLights, r.lastReference.valid);
    r.timer = run.out.timer;
    const BenchEntry& out = run.out;
    log << "bench: [" << e + 1 << "/" << runs.size() << "] " << out.label << ": " << out.msMedian
        << " ms/frame (median), x" << out.msRatio << " of entry 1 (p25-p75 " << out.msRatioP25 << "-" << out.msRatioP75
        << "), wrong " << out.error.wrongPixelPct << " %, image-wrong " << out.image.imageWrongPct << " %";
    if (out.hasFlicker) log << ", flicker excess " << out.flicker << ", world flicker " << out.worldFlicker;
    log << "\n";
  }
  for (EntryRun& run : runs) r.entries.push_back(std::move(run.out));
  r.shaderErrors = shaders.errors();
  for (const auto& err : r.shaderErrors) log << err;
  return r;
}

}  // namespace sl
