// Ray-traced reference visibility for a rendered frame, with an on-disk cache.
// Shared by `shadowlab reference`, `shadowlab bench` and the explorer's error panel:
// the renderer draws the G-buffer (exactly what techniques shade), the ReferenceTracer traces
// shadow rays from it, and the float result is stored under $XDG_CACHE_HOME/shadowlab
// (or ~/.cache/shadowlab) keyed on everything that changes it.
#pragma once

#include "metrics/metrics.h"
#include "reference/reference.h"
#include "render/renderer.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sl {

// Reference visibility of one frame; rows bottom-up like every GL readback.
struct ReferenceImage {
  int width = 0, height = 0;
  std::vector<float> visibility;  // width*height, 1 = lit, 0 for background
  std::vector<uint8_t> valid;     // width*height, 1 where geometry covers the pixel
  // One per Scene::otherLights entry: that light's visibility (empty for an unshadowed light).
  // `visibility` is Scene::light's, the one the visibility metrics compare.
  std::vector<std::vector<float>> otherLights;
  bool cached = false;    // true when it came from the disk cache
  double traceMs = 0;     // time spent tracing (0 when cached)
  std::string cacheFile;  // where it is (or would be) stored
  std::string key;        // the cache key text (for reports and debugging)
};

struct ReferenceSettings {
  int samples = 64;      // light samples per pixel (area lights only)
  bool useCache = true;  // read and write the disk cache
  std::string cacheDir;  // "" = referenceCacheDir()
  int threads = 0;       // 0 = hardware concurrency
};

// $XDG_CACHE_HOME/shadowlab, else $HOME/.cache/shadowlab (created on first write).
std::string referenceCacheDir();
// FNV-1a 64 of the scene file's bytes plus its loaded geometry, light and motion, as hex.
std::string sceneContentHash(const Scene& scene);

// Computes (or loads) references for one scene. Keeps one tracer per scene time, so a path
// or a moving scene traces without rebuilding the BVH every frame.
class ReferenceCache {
 public:
  ReferenceCache(const Scene& scene, ReferenceSettings settings);
  ~ReferenceCache();

  // Reference for the frame the renderer drew last (its G-buffer must be `in`'s frame).
  ReferenceImage forLastFrame(const Renderer& renderer, const FrameInput& in);
  // Reference for `in`: on a cache miss draws the G-buffer first with a private viewport
  // (technique `standard`), so the caller's viewports keep their history.
  ReferenceImage forFrame(Renderer& renderer, const FrameInput& in);
  // Only the cache lookup; false when absent or unreadable.
  bool lookup(const FrameInput& in, ReferenceImage& out) const;
  std::string keyText(const FrameInput& in) const;

 private:
  const ReferenceTracer& tracerAt(double time);
  const Scene& scene_;
  ReferenceSettings settings_;
  std::string sceneHash_;
  std::map<double, std::unique_ptr<ReferenceTracer>> tracers_;
  std::unique_ptr<Viewport> gbufferViewport_;
};

// Visibility channel (R) of an RG visibility target (visibility, confidence), bottom-up rows.
std::vector<float> visibilityChannel(const Texture2D& visibility);
// Visibility channel (R) of a viewport's last frame, bottom-up rows.
std::vector<float> viewportVisibility(const Viewport& viewport);
// Metrics of a viewport's last frame against a reference of the same frame and size
// (the explorer's live error panel calls this).
ErrorMetrics viewportErrorMetrics(const Viewport& viewport, const ReferenceImage& reference);
// image_wrong_pct of a viewport's last frame: its colour target against the same frame shaded
// with the reference's visibility (Renderer::shadeWithVisibility over `in`'s G-buffer), over the
// `valid` pixels whose reference is finite. `in` must be the frame the viewport rendered last.
// imageWrongPct is NaN when the shade program does not build.
// In a scene of several lights `otherLights` are the reference's (ReferenceImage::otherLights)
// and the colours compared sum every light.
ImageErrorMetrics viewportImageError(Renderer& renderer, const FrameInput& in, const Viewport& viewport,
                                     const std::vector<float>& referenceVisibility, const std::vector<uint8_t>& valid,
                                     const std::vector<std::vector<float>>& otherLights = {});
// Each other light's visibility in a viewport's last frame against the reference traced toward
// it: one entry per Scene::otherLights entry (`referenceOthers`, ReferenceImage::otherLights),
// `shadowed` false where the technique made no maps for that light (unshadowed in the file, or
// beyond lights.shadowed) or the reference has none. The bench's `other_lights` and the
// explorer's per-light accuracy rows.
struct LightVisibilityError {
  bool shadowed = false;
  ErrorMetrics error;
};
std::vector<LightVisibilityError> otherLightsVisibilityError(const Viewport& viewport,
                                                             const std::vector<std::vector<float>>& referenceOthers,
                                                             const std::vector<uint8_t>& valid);
// The `error` debug view (RGBA8, bottom-up): grey = agree, orange = false shadow, blue = false light.
std::vector<uint8_t> viewportErrorImage(const Viewport& viewport, const ReferenceImage& reference);
// Grey RGBA8 (bottom-up) of a visibility buffer, for PNGs.
std::vector<uint8_t> visibilityToRgba(const std::vector<float>& visibility);

}  // namespace sl
