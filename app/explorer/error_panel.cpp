#include "explorer/error_panel.h"

#include "bench/reference_cache.h"
#include "explorer/explorer_state.h"
#include "reference/reference.h"
#include "render/renderer.h"

#include <epoxy/gl.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sl {

// ---------------------------------------------------------------------------------------------
// Worker

namespace {

constexpr double kRemeasureSeconds = 0.5;  // metrics of a resting view follow accumulation and edits
constexpr int kReferenceSamples = 64;      // light samples per pixel for area lights (as `bench`)
constexpr size_t kReferencesKept = 4;      // jumping back to a camera needs no new trace
constexpr int kChunks = 48;                // progress and cancellation granularity

double secondsNow() {
  using Clock = std::chrono::steady_clock;
  static const Clock::time_point start = Clock::now();
  return std::chrono::duration<double>(Clock::now() - start).count();
}

}  // namespace

struct ErrorPanel::Job {
  RestKey key;
  const Scene* scene = nullptr;  // read only while the BVH is built (beforeSceneChange joins)
  bool sceneMoves = false;
  std::vector<Light> otherLights;  // Scene::otherLights when the job started
  int threads = 1;
  std::vector<float> position, normal;  // G-buffer readback, rows bottom-up
  std::vector<uint32_t> surface;        // instance + 1, triangle (see Renderer::gSurface)

  std::atomic<int> rowsDone{0};
  std::atomic<bool> building{true};
  std::atomic<bool> cancel{false};
  std::atomic<bool> done{false};
  double started = 0;

  // Results, read by the GL thread only after `done`.
  std::vector<float> visibility;
  std::vector<std::vector<float>> otherVisibility;  // per other light; empty where unshadowed
  std::vector<uint8_t> valid;
  std::string error;
  double buildMs = 0, traceMs = 0;
  std::thread thread;

  void run() {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    try {
      ReferenceTracer tracer(*scene, sceneMoves ? key.time : 0.0);
      scene = nullptr;
      building = false;
      const auto t1 = Clock::now();
      buildMs = std::chrono::duration<double, std::milli>(t1 - t0).count();
      const int w = key.width, h = key.height;
      const size_t n = size_t(w) * size_t(h);
      valid.resize(n);
      for (size_t i = 0; i < n; ++i) valid[i] = position[4 * i + 3] > 0.5f ? 1 : 0;
      visibility.assign(n, 0.0f);
      // Rows are traced in chunks so progress can be shown and a moving camera cancels within
      // one chunk. The tracer sees the whole image with only the chunk's pixels marked covered:
      // pixel indices (which seed the light samples) are then those of a whole-image trace, so
      // the result equals `shadowlab reference` for the same frame.
      std::vector<float> masked(position.size(), 0.0f);
      ReferenceOptions options;
      options.time = key.time;
      options.lightSamples = kReferenceSamples;
      options.threads = threads;
      const int chunkRows = std::max(1, (h + kChunks - 1) / kChunks);
      for (int y0 = 0; y0 < h; y0 += chunkRows) {
        if (cancel) break;
        const int y1 = std::min(h, y0 + chunkRows);
        const size_t a = size_t(y0) * w, b = size_t(y1) * w;
        if (std::any_of(valid.begin() + long(a), valid.begin() + long(b), [](uint8_t v) { return v != 0; })) {
          std::copy(position.begin() + long(4 * a), position.begin() + long(4 * b), masked.begin() + long(4 * a));
          const std::vector<float> part =
              tracer.visibility(GBufferView{w, h, masked.data(), normal.data(), surface.data()}, options);
          std::copy(part.begin() + long(a), part.begin() + long(b), visibility.begin() + long(a));
          std::fill(masked.begin() + long(4 * a), masked.begin() + long(4 * b), 0.0f);
        }
        rowsDone = y1;
      }
      // A scene of several lights: each other shadowed light whole, after the first (the image
      // error shades them all; the visibility metrics and the error view show the first).
      otherVisibility.assign(otherLights.size(), {});
      for (size_t k = 0; k < otherLights.size() && !cancel; ++k) {
        if (!otherLights[k].shadow) continue;
        options.light = &otherLights[k];
        otherVisibility[k] =
            tracer.visibility(GBufferView{w, h, position.data(), normal.data(), surface.data()}, options);
      }
      traceMs = std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
    } catch (const std::exception& e) {
      error = e.what();
    }
    position.clear();
    position.shrink_to_fit();
    normal.clear();
    normal.shrink_to_fit();
    done.store(true, std::memory_order_release);
  }
};

ErrorPanel::ErrorPanel() = default;

ErrorPanel::~ErrorPanel() { joinAll(); }

void ErrorPanel::cancelActive() {
  if (!active_) return;
  active_->cancel = true;
  retiring_.push_back(std::move(active_));
}

void ErrorPanel::joinAll() {
  cancelActive();
  for (auto& job : retiring_)
    if (job->thread.joinable()) job->thread.join();
  retiring_.clear();
}

void ErrorPanel::beforeSceneChange() {
  joinAll();
  references_.clear();
  currentRef_ = 0;
  haveFailed_ = false;
  jobError_.clear();
  ++sceneGeneration_;
}

void ErrorPanel::pollJobs() {
  for (size_t i = 0; i < retiring_.size();) {
    if (retiring_[i]->done.load(std::memory_order_acquire)) {
      retiring_[i]->thread.join();
      retiring_.erase(retiring_.begin() + long(i));
    } else {
      ++i;
    }
  }
  if (!active_ || !active_->done.load(std::memory_order_acquire)) return;
  active_->thread.join();
  Job& job = *active_;
  if (!job.error.empty()) {
    jobError_ = job.error;
    failedKey_ = job.key;
    haveFailed_ = true;
  } else if (!job.cancel) {
    Reference ref;
    ref.key = job.key;
    ref.visibility = std::move(job.visibility);
    ref.otherVisibility = std::move(job.otherVisibility);
    ref.valid = std::move(job.valid);
    ref.id = nextReferenceId_++;
    ref.traceMs = job.traceMs;
    ref.buildMs = job.buildMs;
    references_.push_back(std::move(ref));
    if (references_.size() > kReferencesKept) references_.erase(references_.begin());
  }
  active_.reset();
}

ErrorPanel::JobProgress ErrorPanel::activeProgress() const {
  const Job& job = *active_;
  JobProgress p;
  p.fraction = job.key.height > 0 ? float(job.rowsDone) / float(job.key.height) : 0.0f;
  p.building = job.building;
  p.seconds = now_ - job.started;
  p.threads = job.threads;
  p.samples = kReferenceSamples;
  p.width = job.key.width;
  p.height = job.key.height;
  return p;
}

const ErrorPanel::Reference* ErrorPanel::findReference(const RestKey& key) const {
  for (const Reference& r : references_)
    if (sameRestKey(r.key, key)) return &r;
  return nullptr;
}

const ErrorPanel::Reference* ErrorPanel::currentReference() const {
  for (const Reference& r : references_)
    if (r.id == currentRef_) return &r;
  return nullptr;
}

void ErrorPanel::startJob(ExplorerState& state, Renderer& renderer, const RestKey& key) {
  if (!renderer.hasFreshGBuffer()) return;  // next frame (wantsGBuffer() asks for it)
  const Texture2D& pos = renderer.gPosition();
  if (pos.width() != key.width || pos.height() != key.height) return;  // not this frame's G-buffer
  auto job = std::make_unique<Job>();
  job->key = key;
  job->scene = state.scene.get();
  job->sceneMoves = sceneMoves_;
  job->otherLights = state.scene->otherLights;
  // Leave a core for the window; the tracer's result does not depend on the thread count.
  job->threads = std::max(1, int(std::thread::hardware_concurrency()) - 1);
  job->position = pos.readFloats(4);
  job->normal = renderer.gNormal().readFloats(4);
  job->surface = renderer.gSurface().readUints(4);
  job->started = now_;
  jobError_.clear();
  Job* raw = job.get();
  job->thread = std::thread([raw] { raw->run(); });
  active_ = std::move(job);
}

void ErrorPanel::afterRender(ExplorerState& state, Renderer& renderer, int width, int height, bool rendered) {
  now_ = secondsNow();
  pollJobs();
  rendered_ = rendered && state.scene;
  if (!state.scene) return;
  sceneMoves_ = state.scene->hasMotion();
  RestKey key;
  key.camera = state.camera.camera();
  key.width = width;
  key.height = height;
  key.time = sceneMoves_ ? state.sceneTime : 0.0;
  key.sceneGeneration = sceneGeneration_;
  rest_.update(key, now_);

  // Per-viewport timing windows, always (the ms column does not need a reference).
  const FrameStats& stats = renderer.stats();
  timing_ = renderer.timePasses && !stats.passes.empty();
  int index = 0;                           // the renderer's viewport index: position among the non-empty shown slots
  std::vector<std::pair<int, int>> shown;  // (slot, renderer index)
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()) && i < 4; ++i) {
    if (!state.slots[size_t(i)].viewport) continue;
    shown.emplace_back(i, index);
    ViewportAccuracy& va = viewports_[i];
    const std::string config = configString(state.slots[size_t(i)].viewport->technique);
    if (config != va.timedConfig || !rendered_) {
      va.timedConfig = config;
      va.ownMs.clear();
      va.gbufferMs.clear();
    }
    const ViewportCost cost = viewportFrameMs(stats.passes, index);
    if (rendered_ && timing_ && cost.ownMs >= 0) va.ownMs.add(cost.ownMs);
    // Shown beside the cost, not in it; only frames that drew it count.
    if (rendered_ && timing_ && renderer.hasFreshGBuffer()) va.gbufferMs.add(cost.gbufferMs);
    ++index;
  }

  if (active_ && (!rendered_ || !sameRestKey(active_->key, key))) cancelActive();
  const Reference* ref = rendered_ ? findReference(key) : nullptr;
  currentRef_ = ref ? ref->id : 0;
  if (!ref) {
    const bool failedHere = haveFailed_ && sameRestKey(failedKey_, key);
    if (rendered_ && rest_.resting() && !active_ && retiring_.empty() && !failedHere) startJob(state, renderer, key);
    return;
  }

  const bool wantImage = state.selectedViews.count(kViewName) > 0;
  for (const auto& [slot, renderIndex] : shown) {
    (void)renderIndex;
    ViewportAccuracy& va = viewports_[slot];
    const std::string& config = va.timedConfig;
    const bool due = va.referenceId != ref->id || va.config != config || now_ - va.measuredAt >= kRemeasureSeconds ||
                     (wantImage && va.errorTextureReference != ref->id);
    if (due) measure(state, renderer, *ref, slot, wantImage);
  }
}

void ErrorPanel::measure(ExplorerState& state, Renderer& renderer, const Reference& ref, int slot, bool wantImage) {
  ViewportAccuracy& va = viewports_[slot];
  const Viewport& vp = *state.slots[size_t(slot)].viewport;
  std::vector<float> v;
  try {
    v = viewportVisibility(vp);
  } catch (const std::exception&) {
    return;
  }
  if (v.size() != ref.visibility.size()) return;
  va.metrics = compareVisibility(v.data(), ref.visibility.data(), ref.valid.data(), v.size());
  va.otherLights = otherLightsVisibilityError(vp, ref.otherVisibility, ref.valid);
  // The frame on screen, shaded again with the truth's visibility (the viewports just rendered it).
  FrameInput in;
  in.camera = state.camera.camera();
  in.time = state.sceneTime;
  in.width = ref.key.width;
  in.height = ref.key.height;
  try {
    va.image = viewportImageError(renderer, in, vp, ref.visibility, ref.valid, ref.otherVisibility);
  } catch (const std::exception&) {
    va.image = ImageErrorMetrics{std::numeric_limits<double>::quiet_NaN(), 0};
  }
  va.haveMetrics = true;
  va.config = va.timedConfig;
  va.referenceId = ref.id;
  va.measuredAt = now_;
  va.cost = ViewportCost{va.ownMs.count() ? va.ownMs.median() : -1.0, va.gbufferMs.median()};
  if (wantImage) {
    const std::vector<uint8_t> rgba = errorImage(v.data(), ref.visibility.data(), ref.valid.data(), v.size());
    if (!va.errorTexture || va.errorTexture->width() != ref.key.width || va.errorTexture->height() != ref.key.height)
      va.errorTexture = std::make_unique<Texture2D>(GL_RGBA8, ref.key.width, ref.key.height, "error view");
    va.errorTexture->setFilter(GL_NEAREST, GL_NEAREST);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(va.errorTexture->id(), 0, 0, 0, ref.key.width, ref.key.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        rgba.data());
    va.errorTextureReference = ref.id;
  } else {
    va.errorTextureReference = 0;
  }
  // Only configurations measured with their own timings go on the chart (a fresh edit has
  // none for a frame or two; the next measurement adds it).
  if (va.cost.ownMs >= 0 && va.ownMs.count() >= 3)
    recordChartPoint(points_,
                     ChartPoint{va.config, va.cost.ownMs, va.metrics.wrongPixelPct, slot, va.image.imageWrongPct, {}});
}

const Texture2D* ErrorPanel::errorTexture(int slot) const {
  if (slot < 0 || slot >= 4 || currentRef_ == 0) return nullptr;
  const ViewportAccuracy& va = viewports_[slot];
  if (va.errorTextureReference != currentRef_ || !va.errorTexture) return nullptr;
  return va.errorTexture.get();
}

std::string ErrorPanel::errorViewStatus() const {
  if (active_) {
    const int pct = active_->key.height > 0 ? int(100.0 * active_->rowsDone / active_->key.height) : 0;
    return "tracing reference " + std::to_string(pct) + "%";
  }
  if (!jobError_.empty()) return "reference failed (see panel)";
  if (currentRef_ != 0) return "measuring...";
  if (rest_.lastChange().time && !rest_.resting()) return "scene moving: pause time";
  return "resting camera needed";
}

}  // namespace sl
