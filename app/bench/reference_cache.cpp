// Reference visibility with a disk cache; see reference_cache.h.
#include "bench/reference_cache.h"
#include "technique.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace sl {

namespace {

// Bump when the reference algorithm or the file layout changes: old files are then ignored.
// 2: rays start on the receiver's triangle plane (docs/reference.md); older files are stale.
constexpr uint32_t kFormatVersion = 3;  // 3: the other lights' visibilities follow
constexpr char kMagic[8] = {'S', 'L', 'R', 'E', 'F', 'V', 'I', 'S'};

struct Fnv {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* data, size_t n) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
  }
  template <class T>
  void pod(const T& v) {
    bytes(&v, sizeof(T));
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    pod(v.size());
    if (!v.empty()) bytes(v.data(), v.size() * sizeof(T));
  }
};

std::string hex(uint64_t v) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(v));
  return buf;
}

std::string fmt(float v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}
std::string fmt(const glm::vec3& v) { return fmt(v.x) + "," + fmt(v.y) + "," + fmt(v.z); }

std::string safeName(const std::string& s) {
  std::string out;
  for (char c : s) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return out.empty() ? "scene" : out;
}

}  // namespace

std::string referenceCacheDir() {
  const char* xdg = std::getenv("XDG_CACHE_HOME");
  if (xdg && *xdg) return std::string(xdg) + "/shadowlab";
  const char* home = std::getenv("HOME");
  if (home && *home) return std::string(home) + "/.cache/shadowlab";
  return (std::filesystem::temp_directory_path() / "shadowlab-cache").string();
}

std::string sceneContentHash(const Scene& scene) {
  Fnv f;
  if (!scene.sourcePath.empty()) {
    std::ifstream in(scene.sourcePath, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    f.vec(std::vector<char>(bytes.begin(), bytes.end()));
  }
  // The loaded content too: a glTF referenced by the scene file may change on its own.
  for (const auto& m : scene.meshes) {
    f.vec(m.positions);
    f.vec(m.indices);
    f.pod(m.material);
  }
  for (const auto& mat : scene.materials) {
    f.pod(mat.alphaMask);
    f.pod(mat.alphaCutoff);
    f.pod(mat.baseColor.a);
    f.pod(mat.baseColorTexture);
  }
  for (const auto& t : scene.textures) f.vec(t.rgba);
  for (const auto& inst : scene.instances) {
    f.pod(inst.mesh);
    f.pod(inst.transform);
    f.pod(inst.motion.type);
    f.pod(inst.motion.vector);
    f.pod(inst.motion.period);
  }
  return hex(f.h);
}

ReferenceCache::ReferenceCache(const Scene& scene, ReferenceSettings settings)
    : scene_(scene), settings_(std::move(settings)), sceneHash_(sceneContentHash(scene)) {
  if (settings_.cacheDir.empty()) settings_.cacheDir = referenceCacheDir();
  if (settings_.samples < 1) throw std::invalid_argument("reference: --samples must be at least 1");
}

ReferenceCache::~ReferenceCache() = default;

// A light's part of the cache key: what changes its traced visibility.
static std::string lightKey(const Light& l, int samples) {
  std::ostringstream k;
  k << "samples=" << (l.radius > 0 ? samples : 1) << ";light=" << static_cast<int>(l.type) << ":" << fmt(l.direction)
    << ":" << fmt(l.position) << ":" << fmt(l.fovDeg) << ":" << fmt(l.radius) << ":" << fmt(l.range);
  return k.str();
}

std::string ReferenceCache::keyText(const FrameInput& in) const {
  const Camera& c = in.camera;
  std::ostringstream k;
  k << "v" << kFormatVersion << ";scene=" << scene_.name << ":" << sceneHash_ << ";camera=" << c.name << ":"
    << fmt(c.position) << ":" << fmt(c.target) << ":" << fmt(c.up) << ":" << fmt(c.fovDeg) << ":" << fmt(c.nearPlane)
    << ":" << fmt(c.farPlane) << ";size=" << in.width << "x" << in.height << ";"
    << lightKey(scene_.light, settings_.samples);
  for (const Light& other : scene_.otherLights)
    k << ";other " << (other.shadow ? lightKey(other, settings_.samples) : std::string("unshadowed"));
  k << ";time=" << (scene_.hasMotion() ? fmt(static_cast<float>(in.time)) : std::string("static"))
    << ";gl=" << glRendererName();  // the G-buffer is rasterized: a different driver may differ
  return k.str();
}

static std::string cachePath(const std::string& dir, const std::string& sceneName, const std::string& key) {
  Fnv f;
  f.bytes(key.data(), key.size());
  return dir + "/ref-" + safeName(sceneName) + "-" + hex(f.h) + ".bin";
}

bool ReferenceCache::lookup(const FrameInput& in, ReferenceImage& out) const {
  const std::string key = keyText(in);
  const std::string path = cachePath(settings_.cacheDir, scene_.name, key);
  out.cacheFile = path;
  out.key = key;
  if (!settings_.useCache) return false;
  std::ifstream f(path, std::ios::binary);
  if (!f) return false;
  char magic[8];
  uint32_t version = 0, keyLen = 0;
  int32_t w = 0, h = 0;
  f.read(magic, 8);
  f.read(reinterpret_cast<char*>(&version), 4);
  f.read(reinterpret_cast<char*>(&w), 4);
  f.read(reinterpret_cast<char*>(&h), 4);
  f.read(reinterpret_cast<char*>(&keyLen), 4);
  if (!f || std::memcmp(magic, kMagic, 8) != 0 || version != kFormatVersion || w != in.width || h != in.height ||
      keyLen > 1u << 16)
    return false;
  std::string storedKey(keyLen, '\0');
  f.read(storedKey.data(), keyLen);
  if (!f || storedKey != key) return false;  // hash collision or foreign file
  const size_t n = static_cast<size_t>(w) * h;
  out.visibility.resize(n);
  out.valid.resize(n);
  f.read(reinterpret_cast<char*>(out.visibility.data()), static_cast<std::streamsize>(n * sizeof(float)));
  f.read(reinterpret_cast<char*>(out.valid.data()), static_cast<std::streamsize>(n));
  out.otherLights.assign(scene_.otherLights.size(), {});
  for (size_t k = 0; k < scene_.otherLights.size(); ++k) {
    if (!scene_.otherLights[k].shadow) continue;
    out.otherLights[k].resize(n);
    f.read(reinterpret_cast<char*>(out.otherLights[k].data()), static_cast<std::streamsize>(n * sizeof(float)));
  }
  if (!f) return false;
  out.width = w;
  out.height = h;
  out.cached = true;
  out.traceMs = 0;
  return true;
}

const ReferenceTracer& ReferenceCache::tracerAt(double time) {
  const double t = scene_.hasMotion() ? time : 0.0;
  auto& slot = tracers_[t];
  if (!slot) slot = std::make_unique<ReferenceTracer>(scene_, t);
  return *slot;
}

ReferenceImage ReferenceCache::forLastFrame(const Renderer& renderer, const FrameInput& in) {
  ReferenceImage ref;
  if (lookup(in, ref)) return ref;
  const Texture2D& pos = renderer.gPosition();
  const Texture2D& nrm = renderer.gNormal();
  if (pos.width() != in.width || pos.height() != in.height)
    throw std::runtime_error("reference: the renderer's G-buffer is " + std::to_string(pos.width()) + "x" +
                             std::to_string(pos.height()) + ", not the requested frame size");
  std::vector<float> position = pos.readFloats(4), normal = nrm.readFloats(4);
  const std::vector<uint32_t> surface = renderer.gSurface().readUints(4);
  GBufferView g{in.width, in.height, position.data(), normal.data(), surface.data()};
  ReferenceOptions o;
  o.time = in.time;
  o.lightSamples = settings_.samples;
  o.threads = settings_.threads;
  const ReferenceTracer& tracer = tracerAt(in.time);
  auto t0 = std::chrono::steady_clock::now();
  ref.visibility = tracer.visibility(g, o);
  ref.otherLights.assign(scene_.otherLights.size(), {});
  for (size_t k = 0; k < scene_.otherLights.size(); ++k) {
    if (!scene_.otherLights[k].shadow) continue;
    o.light = &scene_.otherLights[k];
    ref.otherLights[k] = tracer.visibility(g, o);
  }
  ref.traceMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  ref.width = in.width;
  ref.height = in.height;
  ref.valid.resize(static_cast<size_t>(in.width) * in.height);
  for (size_t i = 0; i < ref.valid.size(); ++i) ref.valid[i] = position[4 * i + 3] > 0.5f ? 1 : 0;
  ref.cached = false;
  if (settings_.useCache) {
    std::error_code ec;
    std::filesystem::create_directories(settings_.cacheDir, ec);
    const std::string tmp = ref.cacheFile + ".tmp" + std::to_string(std::rand());
    std::ofstream f(tmp, std::ios::binary);
    if (f) {
      const uint32_t version = kFormatVersion, keyLen = static_cast<uint32_t>(ref.key.size());
      const int32_t w = in.width, h = in.height;
      f.write(kMagic, 8);
      f.write(reinterpret_cast<const char*>(&version), 4);
      f.write(reinterpret_cast<const char*>(&w), 4);
      f.write(reinterpret_cast<const char*>(&h), 4);
      f.write(reinterpret_cast<const char*>(&keyLen), 4);
      f.write(ref.key.data(), keyLen);
      f.write(reinterpret_cast<const char*>(ref.visibility.data()),
              static_cast<std::streamsize>(ref.visibility.size() * sizeof(float)));
      f.write(reinterpret_cast<const char*>(ref.valid.data()), static_cast<std::streamsize>(ref.valid.size()));
      for (const auto& other : ref.otherLights)
        f.write(reinterpret_cast<const char*>(other.data()),
                static_cast<std::streamsize>(other.size() * sizeof(float)));
      f.close();
      // Written whole then renamed, so a concurrent reader never sees half a file.
      if (f) std::filesystem::rename(tmp, ref.cacheFile, ec);
      if (!f || ec) std::filesystem::remove(tmp, ec);
    }
  }
  return ref;
}

ReferenceImage ReferenceCache::forFrame(Renderer& renderer, const FrameInput& in) {
  ReferenceImage ref;
  if (lookup(in, ref)) return ref;
  if (!gbufferViewport_) gbufferViewport_ = std::make_unique<Viewport>(makeTechnique("standard"));
  const bool keep = renderer.keepGBuffer;
  renderer.keepGBuffer = true;  // the reference traces from this frame's G-buffer
  renderer.render(in, {gbufferViewport_.get()});
  renderer.keepGBuffer = keep;
  return forLastFrame(renderer, in);
}

std::vector<float> visibilityChannel(const Texture2D& visibility) {
  const std::vector<float> rg = visibility.readFloats(2);
  std::vector<float> v(rg.size() / 2);
  for (size_t i = 0; i < v.size(); ++i) v[i] = rg[2 * i];
  return v;
}

std::vector<LightVisibilityError> otherLightsVisibilityError(const Viewport& viewport,
                                                             const std::vector<std::vector<float>>& referenceOthers,
                                                             const std::vector<uint8_t>& valid) {
  std::vector<LightVisibilityError> out(referenceOthers.size());
  for (size_t k = 0; k < referenceOthers.size(); ++k) {
    const Texture2D* tex = viewport.otherLightVisibility(k);
    if (!tex || referenceOthers[k].empty()) continue;
    const std::vector<float> v = visibilityChannel(*tex);
    if (v.size() != referenceOthers[k].size() || v.size() != valid.size()) continue;
    out[k] = {true, compareVisibility(v.data(), referenceOthers[k].data(), valid.data(), v.size())};
  }
  return out;
}

std::vector<float> viewportVisibility(const Viewport& viewport) {
  const Texture2D* tex = viewport.visibilityTexture();
  if (!tex) throw std::runtime_error("viewport has not rendered a frame yet");
  return visibilityChannel(*tex);
}

static void checkSameSize(const std::vector<float>& v, const ReferenceImage& r) {
  if (v.size() != r.visibility.size() || r.valid.size() != r.visibility.size())
    throw std::runtime_error("viewport and reference differ in size (" + std::to_string(v.size()) + " vs " +
                             std::to_string(r.visibility.size()) + " pixels)");
}

ErrorMetrics viewportErrorMetrics(const Viewport& viewport, const ReferenceImage& reference) {
  std::vector<float> v = viewportVisibility(viewport);
  checkSameSize(v, reference);
  return compareVisibility(v.data(), reference.visibility.data(), reference.valid.data(), v.size());
}

ImageErrorMetrics viewportImageError(Renderer& renderer, const FrameInput& in, const Viewport& viewport,
                                     const std::vector<float>& referenceVisibility, const std::vector<uint8_t>& valid,
                                     const std::vector<std::vector<float>>& otherLights) {
  const Texture2D* color = viewport.colorTexture();
  if (!color) throw std::runtime_error("viewport has not rendered a frame yet");
  const size_t n = referenceVisibility.size();
  if (valid.size() != n || size_t(color->width()) * size_t(color->height()) != n)
    throw std::runtime_error("viewport and reference differ in size (" +
                             std::to_string(size_t(color->width()) * size_t(color->height())) + " vs " +
                             std::to_string(n) + " pixels)");
  const std::vector<unsigned char> truth = renderer.shadeWithVisibility(in, referenceVisibility, otherLights);
  if (truth.empty()) return ImageErrorMetrics{std::numeric_limits<double>::quiet_NaN(), 0};
  std::vector<uint8_t> counted(valid);
  for (size_t i = 0; i < n; ++i) counted[i] = counted[i] && std::isfinite(referenceVisibility[i]);
  for (const auto& other : otherLights)
    for (size_t i = 0; i < other.size() && i < n; ++i) counted[i] = counted[i] && std::isfinite(other[i]);
  return compareImages(color->readRgba8().data(), truth.data(), counted.data(), n);
}

std::vector<uint8_t> viewportErrorImage(const Viewport& viewport, const ReferenceImage& reference) {
  std::vector<float> v = viewportVisibility(viewport);
  checkSameSize(v, reference);
  return errorImage(v.data(), reference.visibility.data(), reference.valid.data(), v.size());
}

std::vector<uint8_t> visibilityToRgba(const std::vector<float>& visibility) {
  std::vector<uint8_t> rgba(visibility.size() * 4, 255);
  for (size_t i = 0; i < visibility.size(); ++i) {
    const float v = visibility[i];
    // NaN shows as magenta, like the error view.
    if (!std::isfinite(v)) {
      rgba[4 * i] = 255, rgba[4 * i + 1] = 0, rgba[4 * i + 2] = 255;
      continue;
    }
    const auto g = static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    rgba[4 * i] = rgba[4 * i + 1] = rgba[4 * i + 2] = g;
  }
  return rgba;
}

}  // namespace sl
