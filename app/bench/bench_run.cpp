// Planning and running `shadowlab bench`; see bench.h.
#include "bench/bench.h"

#include "cli/args.h"
#include "gl/headless_context.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <sstream>
#include <thread>

namespace sl {

namespace {

std::vector<std::string> splitList(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream in(s);
  while (std::getline(in, cur, sep))
    if (!cur.empty()) out.push_back(cur);
  return out;
}

std::pair<std::string, std::string> splitAssignment(const std::string& a, const std::string& option) {
  auto eq = a.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == a.size())
    throw ArgError(option + " expects key=value, got '" + a + "'");
  return {a.substr(0, eq), a.substr(eq + 1)};
}

// "shadowmap.size, bias.mode, ..." of all techniques, for error messages.
std::string knownKeys(const std::vector<Technique>& ts) {
  std::vector<std::string> keys;
  for (const auto& t : ts)
    for (const auto& d : t.params.decls())
      if (std::find(keys.begin(), keys.end(), d.key) == keys.end()) keys.push_back(d.key);
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

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

}  // namespace

std::vector<BenchPlanEntry> planBench(const BenchOptions& o) {
  if (o.techniques.empty()) throw ArgError("--techniques a,b,c is required (see `shadowlab list`)");
  if (o.frames < 1) throw ArgError("--frames must be at least 1");
  if (o.warmup < 0) throw ArgError("--warmup must be 0 or more");
  std::vector<Technique> base;
  for (const auto& id : o.techniques) base.push_back(makeTechnique(id));  // ParamError names unknown presets

  for (const auto& a : o.sets) {
    auto [key, value] = splitAssignment(a, "--set");
    bool any = false;
    for (auto& t : base)
      if (t.params.has(key)) {
        t.params.setFromString(key, value);  // ParamError for a bad value
        any = true;
      }
    if (!any)
      throw ArgError("--set " + a + ": no technique in --techniques has a parameter '" + key +
                     "' (keys: " + knownKeys(base) + ")");
  }

  struct Sweep {
    std::string key;
    std::vector<std::string> values;
  };
  std::vector<Sweep> sweeps;
  for (const auto& s : o.sweeps) {
    auto [key, list] = splitAssignment(s, "--sweep");
    Sweep sw{key, splitList(list, ',')};
    if (sw.values.empty()) throw ArgError("--sweep " + s + ": no values");
    for (const auto& other : sweeps)
      if (other.key == key) throw ArgError("--sweep " + key + " given twice");
    bool any = false;
    for (const auto& t : base)
      if (t.params.has(key)) {
        any = true;
        Technique probe = t;
        for (const auto& v : sw.values) probe.params.setFromString(key, v);  // validate every value now
      }
    if (!any)
      throw ArgError("--sweep " + s + ": no technique in --techniques has a parameter '" + key +
                     "' (keys: " + knownKeys(base) + ")");
    sweeps.push_back(sw);
  }

  std::vector<BenchPlanEntry> plan;
  for (const auto& t : base) {
    // Cartesian product over the sweeps this technique has; the others collapse to one point.
    std::vector<const Sweep*> dims;
    for (const auto& s : sweeps)
      if (t.params.has(s.key)) dims.push_back(&s);
    std::vector<size_t> idx(dims.size(), 0);
    while (true) {
      BenchPlanEntry e{t, {}};
      for (size_t d = 0; d < dims.size(); ++d) {
        e.technique.params.setFromString(dims[d]->key, dims[d]->values[idx[d]]);
        e.sweepPoint.emplace_back(dims[d]->key, dims[d]->values[idx[d]]);
      }
      plan.push_back(std::move(e));
      bool carried = true;  // odometer increment over the sweep dimensions
      for (size_t d = dims.size(); d-- > 0;) {
        if (++idx[d] < dims[d]->values.size()) {
          carried = false;
          break;
        }
        idx[d] = 0;
      }
      if (carried) break;
    }
  }
  return plan;
}

BenchResult runBench(const BenchOptions& o, std::ostream& log) {
  std::vector<BenchPlanEntry> plan = planBench(o);
  BenchResult r;
  r.options = o;
  r.date = isoDateUtc();
  r.cores = std::thread::hardware_concurrency();
  r.cpu = cpuModel();

  Scene scene = loadScene(o.scene, defaultAssetsDir());
  r.sceneName = scene.name;
  Camera camera = scene.cameras.front();
  if (!o.camera.empty()) {
    const Camera* c = scene.findCamera(o.camera);
    if (!c) throw ArgError("scene '" + scene.name + "' has no camera '" + o.camera + "'");
    camera = *c;
  }
  const CameraPath* path = nullptr;
  if (!o.path.empty()) {
    path = scene.findPath(o.path);
    if (!path) throw ArgError("scene '" + scene.name + "' has no camera path '" + o.path + "'");
  }
  r.options.camera = path ? "" : camera.name;

  // The frames every entry renders: a still camera and time (convergence), or the path at 30 fps.
  std::vector<FrameInput> inputs(o.frames);
  for (int f = 0; f < o.frames; ++f) {
    FrameInput& in = inputs[f];
    in.width = o.width;
    in.height = o.height;
    in.time = path ? o.time + f / 30.0 : o.time;
    in.camera = path ? path->sample(static_cast<float>(o.time + f / 30.0), camera) : camera;
  }
  const bool still = path == nullptr;

  HeadlessContext context;
  ShaderLibrary shaders(o.shaderDir.empty() ? defaultShaderDir() : o.shaderDir);
  Renderer renderer(shaders);
  renderer.setScene(scene);
  renderer.timePasses = true;
  r.renderer = glRendererName();

  // References first (each draws its own G-buffer), so no entry's history is disturbed.
  ReferenceSettings rs;
  rs.samples = o.samples;
  rs.useCache = o.useCache;
  r.referenceSamples = scene.light.radius > 0 ? o.samples : 1;
  ReferenceCache cache(scene, rs);
  std::vector<ReferenceImage> refs;
  for (size_t f = 0; f < (still ? 1 : inputs.size()); ++f) {
    refs.push_back(cache.forFrame(renderer, inputs[f]));
    if (refs.back().cached) {
      ++r.referencesCached;
    } else {
      ++r.referencesTraced;
      r.referenceTraceMs += refs.back().traceMs;
    }
  }
  log << "bench: reference " << (still ? "frame" : "frames") << ": " << r.referencesTraced << " traced ("
      << static_cast<long long>(r.referenceTraceMs) << " ms), " << r.referencesCached << " cached\n";
  auto refFor = [&](int f) -> const ReferenceImage& { return refs[still ? 0 : f]; };
  // Measured frames time only what the technique needs: no G-buffer kept for readback.
  renderer.keepGBuffer = false;

  // Flicker is measured over pixels covered in every frame, for technique and reference alike.
  std::vector<uint8_t> commonValid = refs.front().valid;
  for (const auto& ref : refs)
    for (size_t i = 0; i < commonValid.size(); ++i) commonValid[i] &= ref.valid[i];
  if (!still) {
    std::vector<std::vector<float>> refFrames;
    for (const auto& ref : refs) refFrames.push_back(ref.visibility);
    r.referenceFlicker = meanTemporalChange(refFrames, commonValid.data());
    r.referenceChangeMap = temporalChangeMap(refFrames, commonValid.data());
    r.pathValid = commonValid;
  }
  r.lastReference = refs.back();

  // Global warm-up: build every entry's shaders and let the driver settle (llvmpipe spins up its
  // threads and JIT caches) before anything is timed, so the first entries are not penalised.
  {
    std::vector<std::unique_ptr<Viewport>> vps;
    for (const auto& p : plan) vps.push_back(std::make_unique<Viewport>(p.technique));
    for (int w = 0; w < std::max(1, o.warmup); ++w)
      for (auto& vp : vps) {
        FrameInput in = inputs.front();
        in.cut = w == 0;
        renderer.render(in, {vp.get()});
      }
  }

  for (size_t e = 0; e < plan.size(); ++e) {
    const BenchPlanEntry& p = plan[e];
    BenchEntry out;
    out.technique = p.technique.presetId;
    out.label = p.technique.presetId;
    for (const auto& [k, v] : p.sweepPoint) out.label += " " + k + "=" + v;
    for (const auto& d : p.technique.params.decls())
      out.params.emplace_back(d.key, formatValue(d, p.technique.params.get(d.key)));
    out.sweepPoint = p.sweepPoint;
    out.frames = o.frames;

    Viewport viewport(p.technique);
    // Warm-up: shader builds, target allocation, driver caches. Then forget the history.
    for (int w = 0; w < o.warmup; ++w) {
      FrameInput in = inputs.front();
      in.cut = w == 0;
      renderer.render(in, {&viewport});
    }
    viewport.setTechnique(p.technique);
    // Coherent camera motion into the measured view (filled history), not timed: along the path
    // itself when there is one, else a rotation about the target.
    for (int a = 0; a < o.approach; ++a) {
      FrameInput in = inputs.front();
      in.cut = a == 0;
      if (path) {
        in.time = o.time - (o.approach - a) / 30.0;
        in.camera = path->sample(static_cast<float>(in.time), camera);
        renderer.render(in, {&viewport});
        continue;
      }
      const float angle =
          glm::radians(o.approachDeg) * static_cast<float>(o.approach - a) / static_cast<float>(o.approach);
      const glm::vec3 offset = in.camera.position - in.camera.target;
      in.camera.position = in.camera.target +
                           glm::vec3(glm::rotate(glm::mat4(1.0f), angle, glm::vec3(0, 1, 0)) * glm::vec4(offset, 0.0f));
      in.cut = a == 0;
      renderer.render(in, {&viewport});
    }

    std::vector<double> frameMs;
    std::map<std::string, std::vector<double>> passMs;
    std::vector<std::string> passOrder;
    std::vector<std::vector<float>> frames;
    for (int f = 0; f < o.frames; ++f) {
      FrameInput in = inputs[f];
      in.cut = f == 0 && o.approach == 0;
      renderer.render(in, {&viewport});
      const FrameStats& st = renderer.stats();
      frameMs.push_back(st.frameMs);
      out.timer = st.timer;
      for (const auto& pt : st.passes) {
        if (!passMs.count(pt.name)) passOrder.push_back(pt.name);
        passMs[pt.name].push_back(pt.ms);
      }
      std::vector<float> vis = viewportVisibility(viewport);
      const ReferenceImage& ref = refFor(f);
      ErrorMetrics m = compareVisibility(vis.data(), ref.visibility.data(), ref.valid.data(), vis.size());
      out.convergence.push_back(m.wrongPixelPct);
      if (f + 1 == o.frames) {
        out.error = m;
        out.nonfinite = 0;
        for (float v : vis) out.nonfinite += std::isfinite(v) ? 0 : 1;
        out.lastVisibility = vis;
      }
      if (!still) frames.push_back(std::move(vis));
    }
    out.msMedian = median(frameMs);
    out.msP95 = p95(frameMs);
    for (const auto& name : passOrder) out.passes.push_back({name, median(passMs[name])});
    if (!still) {
      out.hasFlicker = true;
      out.flickerTechnique = meanTemporalChange(frames, commonValid.data());
      out.changeMap = temporalChangeMap(frames, commonValid.data());
      out.flickerReference = r.referenceFlicker;
      out.flicker = flickerExcess(out.changeMap, r.referenceChangeMap, commonValid.data());
    }
    r.timer = out.timer;
    log << "bench: [" << e + 1 << "/" << plan.size() << "] " << out.label << ": " << out.msMedian
        << " ms/frame (median), wrong " << out.error.wrongPixelPct << " %\n";
    r.entries.push_back(std::move(out));
  }
  r.shaderErrors = shaders.errors();
  for (const auto& err : r.shaderErrors) log << err;
  return r;
}

}  // namespace sl
