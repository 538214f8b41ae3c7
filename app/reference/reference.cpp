// Ray-traced shadow reference with Embree 3. See docs/reference.md for what is traced and why.
#include "reference/reference.h"

#include "scene/volume_density.h"

#include <embree3/rtcore.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <stdexcept>
#include <thread>

namespace sl {

// Outside the anonymous namespace: ReferenceTracer::Impl holds these (GCC warns of a member whose
// type has internal linkage).
// What the alpha filter needs for one alpha-masked geometry. Copied out of the Scene so the
// tracer stays valid if the caller's Scene goes away or is edited after construction.
struct AlphaGeometry {
  std::vector<glm::vec2> uvs;
  std::vector<uint32_t> indices;
  Texture texture;  // empty (width 0) when the material has no base colour texture
  float baseAlpha = 1.0f;
  float cutoff = 0.5f;

  float alphaAt(uint32_t prim, float u, float v) const {
    float alpha = baseAlpha;
    if (texture.width <= 0 || texture.height <= 0) return alpha;
    const glm::vec2& uv0 = uvs[indices[3 * prim + 0]];
    const glm::vec2& uv1 = uvs[indices[3 * prim + 1]];
    const glm::vec2& uv2 = uvs[indices[3 * prim + 2]];
    const glm::vec2 uv = (1.0f - u - v) * uv0 + u * uv1 + v * uv2;
    // Nearest texel, wrap = repeat. glTF puts uv (0,0) at the image's top-left and texture row 0
    // is the top row, so v maps to rows without a flip.
    auto wrap = [](float t, int size) {
      int i = static_cast<int>(std::floor(t * static_cast<float>(size)));
      i %= size;
      return i < 0 ? i + size : i;
    };
    const int x = wrap(uv.x, texture.width);
    const int y = wrap(uv.y, texture.height);
    const size_t texel = (static_cast<size_t>(y) * texture.width + x) * 4;
    return alpha * (texture.rgba[texel + 3] / 255.0f);
  }
};

namespace {

// Occlusion filter: rejects hits on alpha-masked texels so shadow rays pass through holes.
void alphaOcclusionFilter(const RTCFilterFunctionNArguments* args) {
  const auto* geometry = static_cast<const AlphaGeometry*>(args->geometryUserPtr);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
    const float u = RTCHitN_u(args->hit, args->N, i);
    const float v = RTCHitN_v(args->hit, args->N, i);
    if (geometry->alphaAt(prim, u, v) < geometry->cutoff) args->valid[i] = 0;
  }
}

// A shadow ray's running transmittance through semi-transparent (blended) surfaces. Embree
// passes the context to the filters; ours starts with Embree's own, so the filter casts back.
struct TransmittanceContext {
  RTCIntersectContext context;
  float transmittance = 1.0f;
  // Hits already counted: with spatial splits (high-quality builds) a triangle can sit in two
  // leaves and be reported twice; a strand must attenuate once.
  uint64_t seen[64];
  int seenCount = 0;
};

// Occlusion filter of blended geometry (hair, glTF BLEND): multiplies the ray's transmittance
// by 1 - alpha and rejects the hit, so the ray goes on to the light.
void blendOcclusionFilter(const RTCFilterFunctionNArguments* args) {
  const auto* geometry = static_cast<const AlphaGeometry*>(args->geometryUserPtr);
  auto* ctx = reinterpret_cast<TransmittanceContext*>(args->context);
  for (unsigned i = 0; i < args->N; ++i) {
    if (args->valid[i] == 0) continue;
    const uint32_t prim = RTCHitN_primID(args->hit, args->N, i);
    const uint64_t key = (static_cast<uint64_t>(RTCHitN_geomID(args->hit, args->N, i)) << 32) | prim;
    bool counted = false;
    for (int k = 0; k < ctx->seenCount && !counted; ++k) counted = ctx->seen[k] == key;
    if (!counted) {
      if (ctx->seenCount < 64) ctx->seen[ctx->seenCount++] = key;
      const float alpha = std::clamp(
          geometry->alphaAt(prim, RTCHitN_u(args->hit, args->N, i), RTCHitN_v(args->hit, args->N, i)), 0.0f, 1.0f);
      ctx->transmittance *= 1.0f - alpha;
    }
    args->valid[i] = 0;
  }
}

// March steps per volume crossed by a shadow ray (the deep map uses deep.volume_steps per texel).
constexpr int kReferenceVolumeSteps = 256;

// Stateless integer hash (a splitmix64-style finaliser): the jitter of a light sample depends
// only on (pixel, sample, dimension), so results do not depend on the thread count or order.
uint64_t mixBits(uint64_t x) {
  x += 0x9e3779b97f4a7c15ull;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
  return x ^ (x >> 31);
}

float hashToUnit(uint64_t pixel, uint64_t sample, uint64_t dimension) {
  const uint64_t h = mixBits(pixel * 0x100000001b3ull ^ mixBits(sample * 4 + dimension));
  return static_cast<float>(h >> 40) * (1.0f / 16777216.0f);  // 24 bits -> [0,1)
}

// Shirley-Chiu concentric mapping of the unit square onto the unit disk: keeps the strata of the
// jittered grid compact on the disk, so stratification still reduces variance.
glm::vec2 concentricDisk(float a, float b) {
  const float x = 2.0f * a - 1.0f;
  const float y = 2.0f * b - 1.0f;
  if (x == 0.0f && y == 0.0f) return glm::vec2(0.0f);
  constexpr float kQuarterPi = 0.78539816339f;
  float r, phi;
  if (std::abs(x) > std::abs(y)) {
    r = x;
    phi = kQuarterPi * (y / x);
  } else {
    r = y;
    phi = 2.0f * kQuarterPi - kQuarterPi * (x / y);
  }
  return r * glm::vec2(std::cos(phi), std::sin(phi));
}

// Any two unit vectors spanning the plane perpendicular to the unit vector n.
void orthonormalBasis(const glm::vec3& n, glm::vec3& t, glm::vec3& b) {
  const glm::vec3 helper = std::abs(n.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  t = glm::normalize(glm::cross(helper, n));
  b = glm::cross(n, t);
}

bool isFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

// Where a shadow ray starts: the receiving point on its own plane and that plane's normal.
struct RayStart {
  glm::vec3 origin{0.0f};
  glm::dvec3 plane{0.0};  // unit normal of the surface at the origin, on the side the camera sees
  bool hasPlane = false;
  double tolerance = 0.0;  // heights above the plane that float positions cannot resolve
};

// A triangle's world-space vertices as the tracer stores them (for a receiver's exact plane).
struct TracedMesh {
  std::vector<glm::vec3> world;
  std::vector<uint32_t> indices;
};

// Float positions hold about 24 bits: a point and the plane through its triangle agree to a few
// units in the last place of their largest coordinate. 2^-20 is 8 such units.
constexpr double kPlaneTolerance = 1.0 / 1048576.0;
constexpr double kMinTolerance = 1e-9;  // metres; only matters for points at the world origin

double maxAbs(const glm::dvec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

struct ReferenceTracer::Impl {
  RTCDevice device = nullptr;
  RTCScene scene = nullptr;
  std::vector<std::unique_ptr<AlphaGeometry>> alphaGeometries;  // user data of the filters
  std::vector<TracedMesh> meshes;                               // by scene instance index
  Light light;
  Scene media;  // the scene's volumes only (the density the deep map integrates too)

  std::mutex errorMutex;
  std::string firstError;  // filled by the Embree error callback

  static void onEmbreeError(void* user, RTCError code, const char* message) {
    auto* self = static_cast<Impl*>(user);
    std::lock_guard<std::mutex> lock(self->errorMutex);
    if (self->firstError.empty())
      self->firstError =
          "Embree error " + std::to_string(static_cast<int>(code)) + ": " + (message ? message : "(no message)");
  }

  void throwIfEmbreeFailed(const char* stage) {
    std::lock_guard<std::mutex> lock(errorMutex);
    if (!firstError.empty())
      throw std::runtime_error(std::string("ReferenceTracer: ") + stage + " failed: " + firstError);
  }

  ~Impl() {
    if (scene) rtcReleaseScene(scene);
    if (device) rtcReleaseDevice(device);
  }

  // Light fraction along one direction from a ray start: 0 behind an opaque hit, else the
  // product of 1 - alpha of the blended surfaces crossed and exp(-integral of sigma_t) of the
  // volumes. Hits nearer than the height the positions cannot resolve (tolerance above the
  // receiver's plane) are the receiver's own surface.
  float transmittance(const RayStart& start, const glm::vec3& dir, float tfar) const {
    double tnear = start.tolerance;
    if (start.hasPlane) tnear /= glm::dot(start.plane, glm::dvec3(dir));  // > 0: checked by callers
    if (!(tnear < tfar)) return 1.0f;
    TransmittanceContext context;
    rtcInitIntersectContext(&context.context);
    RTCRay ray;
    ray.org_x = start.origin.x;
    ray.org_y = start.origin.y;
    ray.org_z = start.origin.z;
    ray.tnear = static_cast<float>(tnear);
    ray.dir_x = dir.x;
    ray.dir_y = dir.y;
    ray.dir_z = dir.z;
    ray.time = 0.0f;
    ray.tfar = tfar;
    ray.mask = 0xffffffffu;
    ray.id = 0;
    ray.flags = 0;
    rtcOccluded1(scene, &context.context, &ray);
    if (!(ray.tfar >= 0.0f)) return 0.0f;  // Embree sets tfar to -inf on an occluding hit
    float t = context.transmittance;
    if (!media.volumes.empty() && t > 0.0f)
      t *= volumeTransmittance(media, start.origin, dir, tfar, kReferenceVolumeSteps);
    return std::clamp(t, 0.0f, 1.0f);
  }

  // Direction from p to the centre of the light; false when p is outside a spot cone or beyond
  // a point light's range.
  bool centreToLight(const Light& light, const glm::vec3& p, glm::vec3& toLight, float& distance) const {
    if (light.type == Light::Type::Directional) {
      toLight = -light.direction;
      distance = std::numeric_limits<float>::infinity();
      return true;
    }
    const glm::vec3 d = light.position - p;
    distance = glm::length(d);
    if (!(distance > 0.0f)) return false;
    toLight = d / distance;
    if (light.type == Light::Type::Point) return !(light.range > 0.0f) || distance <= light.range;
    const float cosHalf = std::cos(glm::radians(light.fovDeg * 0.5f));
    return glm::dot(-toLight, light.direction) >= cosHalf;
  }

  // The ray start for p: on the exact plane of its triangle when the G-buffer names it (the
  // rasterizer's interpolated position drifts off the plane by its own rounding), else p with
  // the plane of the shading normal n (0 = none).
  RayStart rayStart(const glm::vec3& p, const glm::vec3& n, int instance, int triangle) const {
    RayStart s;
    s.origin = p;
    s.plane = glm::dvec3(n);
    s.hasPlane = glm::length(n) > 0.0f;
    double scale = maxAbs(glm::dvec3(p));
    if (instance >= 0 && static_cast<size_t>(instance) < meshes.size() && triangle >= 0 &&
        3 * static_cast<size_t>(triangle) + 2 < meshes[instance].indices.size()) {
      const TracedMesh& m = meshes[instance];
      const glm::dvec3 a(m.world[m.indices[3 * triangle]]), b(m.world[m.indices[3 * triangle + 1]]),
          c(m.world[m.indices[3 * triangle + 2]]);
      glm::dvec3 facet = glm::cross(b - a, c - a);
      const double length = glm::length(facet);
      if (length > 0.0 && std::isfinite(length)) {
        facet /= length;
        if (s.hasPlane && glm::dot(facet, glm::dvec3(n)) < 0.0) facet = -facet;
        const glm::dvec3 onPlane = glm::dvec3(p) - facet * glm::dot(facet, glm::dvec3(p) - a);
        s.origin = glm::vec3(onPlane);
        s.plane = facet;
        s.hasPlane = true;
        scale = std::max({maxAbs(onPlane), maxAbs(a), maxAbs(b), maxAbs(c)});
      }
    }
    s.tolerance = std::max(kPlaneTolerance * scale, kMinTolerance);
    return s;
  }

  // Fractional visibility of the light from surface point p with shading normal n (see docs).
  float shade(const Light& light, const glm::vec3& p, glm::vec3 n, int instance, int triangle, int gridSize,
              uint64_t pixel) const {
    glm::vec3 toLight;
    float distance;
    if (!isFinite(p) || !centreToLight(light, p, toLight, distance)) return 0.0f;
    const float nLength = glm::length(n);
    const bool hasNormal = std::isfinite(nLength) && nLength > 1e-12f;
    n = hasNormal ? n / nLength : glm::vec3(0.0f);
    // Facing away from the light: N.L zeroes the shading anyway, and a ray from there could
    // leak through thin closed geometry.
    if (hasNormal && glm::dot(n, toLight) <= 0.0f) return 0.0f;
    const RayStart start = rayStart(p, n, instance, triangle);
    // The triangle itself faces away (the shadow terminator of a smooth-shaded mesh): the
    // surface shadows itself, as a ray from inside the closed mesh would find.
    if (start.hasPlane && glm::dot(start.plane, glm::dvec3(toLight)) <= 0.0) return 0.0f;

    if (light.radius <= 0.0f || gridSize <= 0) {
      const float tfar = light.type == Light::Type::Directional ? distance : distance * (1.0f - 1e-4f);
      return transmittance(start, toLight, tfar);
    }

    // A spot's disk faces its direction; a point light's sphere shows p the disk facing it.
    glm::vec3 tangent, bitangent;
    orthonormalBasis(light.type == Light::Type::Point ? -toLight : glm::normalize(light.direction), tangent, bitangent);
    float visible = 0.0f;
    const int total = gridSize * gridSize;
    for (int s = 0; s < total; ++s) {
      const float a = (static_cast<float>(s % gridSize) + hashToUnit(pixel, s, 0)) / gridSize;
      const float b = (static_cast<float>(s / gridSize) + hashToUnit(pixel, s, 1)) / gridSize;
      const glm::vec2 disk = concentricDisk(a, b) * light.radius;
      const glm::vec3 offset = disk.x * tangent + disk.y * bitangent;
      glm::vec3 dir;
      float tfar;
      if (light.type == Light::Type::Directional) {
        // Disk of radius `radius` at unit distance: a cone of directions of tangent `radius`.
        dir = glm::normalize(-light.direction + offset);
        tfar = std::numeric_limits<float>::infinity();
      } else {
        const glm::vec3 toSample = light.position + offset - start.origin;
        const float length = glm::length(toSample);
        if (!(length > 0.0f)) continue;
        dir = toSample / length;
        tfar = length * (1.0f - 1e-4f);
      }
      // Parts of the light below the surface's horizon are hidden by the surface itself.
      if (start.hasPlane && glm::dot(start.plane, glm::dvec3(dir)) <= 0.0) continue;
      visible += transmittance(start, dir, tfar);
    }
    return visible / static_cast<float>(total);
  }
};

// Alpha-masked and blended materials: the geometry gets an occlusion filter that reads its
// alpha (masks cut holes; blended surfaces attenuate the light fraction reaching the receiver),
// with the data the filter needs kept in `owned`.
static void attachAlphaFilter(RTCGeometry geom, const Scene& scene, const Mesh& mesh, size_t triCount,
                              std::vector<std::unique_ptr<AlphaGeometry>>& owned) {
  const bool validMaterial = mesh.material >= 0 && static_cast<size_t>(mesh.material) < scene.materials.size();
  if (!validMaterial || !(scene.materials[mesh.material].alphaMask || scene.materials[mesh.material].alphaBlend))
    return;
  const Material& material = scene.materials[mesh.material];
  auto alpha = std::make_unique<AlphaGeometry>();
  alpha->uvs = mesh.uvs;
  alpha->uvs.resize(mesh.positions.size(), glm::vec2(0.0f));  // tolerate missing uvs
  alpha->indices.assign(mesh.indices.begin(), mesh.indices.begin() + 3 * triCount);
  alpha->baseAlpha = material.baseColor.a;
  alpha->cutoff = material.alphaCutoff;
  const int t = material.baseColorTexture;
  if (t >= 0 && static_cast<size_t>(t) < scene.textures.size()) {
    const Texture& texture = scene.textures[t];
    if (texture.rgba.size() >= static_cast<size_t>(texture.width) * texture.height * 4) alpha->texture = texture;
  }
  rtcSetGeometryUserData(geom, alpha.get());
  rtcSetGeometryOccludedFilterFunction(geom, material.alphaBlend ? &blendOcclusionFilter : &alphaOcclusionFilter);
  owned.push_back(std::move(alpha));
}

ReferenceTracer::ReferenceTracer(const Scene& scene, double time) : impl_(new Impl) {
  std::unique_ptr<Impl> impl(impl_);  // released only if construction succeeds
  impl->light = scene.light;
  impl->media.volumes = scene.volumes;
  if (glm::length(impl->light.direction) > 0.0f) impl->light.direction = glm::normalize(impl->light.direction);

  impl->device = rtcNewDevice(nullptr);
  if (!impl->device) {
    const RTCError code = rtcGetDeviceError(nullptr);
    throw std::runtime_error("ReferenceTracer: could not create the Embree device (error " +
                             std::to_string(static_cast<int>(code)) + "); is the CPU supported by libembree3?");
  }
  rtcSetDeviceErrorFunction(impl->device, &Impl::onEmbreeError, impl.get());
  impl->scene = rtcNewScene(impl->device);
  rtcSetSceneBuildQuality(impl->scene, RTC_BUILD_QUALITY_HIGH);

  size_t triangles = 0;
  impl->meshes.resize(scene.instances.size());
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& inst = scene.instances[i];
    if (inst.mesh < 0 || static_cast<size_t>(inst.mesh) >= scene.meshes.size())
      throw std::runtime_error("ReferenceTracer: instance '" + inst.name + "' refers to mesh " +
                               std::to_string(inst.mesh) + ", which does not exist");
    const Mesh& mesh = scene.meshes[inst.mesh];
    const size_t triCount = mesh.indices.size() / 3;
    if (triCount == 0 || mesh.positions.empty()) continue;
    for (uint32_t index : mesh.indices)
      if (index >= mesh.positions.size())
        throw std::runtime_error("ReferenceTracer: mesh '" + mesh.name + "' has an index out of range");

    const glm::mat4 toWorld = inst.transformAt(time);
    TracedMesh& traced = impl->meshes[i];
    traced.world.resize(mesh.positions.size());
    traced.indices.assign(mesh.indices.begin(), mesh.indices.begin() + 3 * triCount);
    RTCGeometry geom = rtcNewGeometry(impl->device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof(float), mesh.positions.size()));
    auto* indices = static_cast<uint32_t*>(
        rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), triCount));
    if (!vertices || !indices) {
      rtcReleaseGeometry(geom);
      impl->throwIfEmbreeFailed("allocating geometry buffers");
      throw std::runtime_error("ReferenceTracer: could not allocate Embree geometry buffers");
    }
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::vec3 world = glm::vec3(toWorld * glm::vec4(mesh.positions[v], 1.0f));
      vertices[3 * v + 0] = world.x;
      vertices[3 * v + 1] = world.y;
      vertices[3 * v + 2] = world.z;
      traced.world[v] = world;
    }
    std::copy(mesh.indices.begin(), mesh.indices.begin() + 3 * triCount, indices);
    rtcSetGeometryBuildQuality(geom, RTC_BUILD_QUALITY_HIGH);

    attachAlphaFilter(geom, scene, mesh, triCount, impl->alphaGeometries);
    rtcCommitGeometry(geom);
    rtcAttachGeometryByID(impl->scene, geom, static_cast<unsigned>(i));  // geomID = instance index
    rtcReleaseGeometry(geom);                                            // the scene keeps its own reference
    triangles += triCount;
  }
  if (triangles == 0)
    throw std::runtime_error("ReferenceTracer: the scene has no triangles to trace (" +
                             std::to_string(scene.instances.size()) + " instances)");
  rtcCommitScene(impl->scene);
  impl->throwIfEmbreeFailed("building the scene");
  impl.release();
}

ReferenceTracer::~ReferenceTracer() { delete impl_; }

std::vector<float> ReferenceTracer::visibility(const GBufferView& gbuffer, const ReferenceOptions& options) const {
  if (gbuffer.width <= 0 || gbuffer.height <= 0) return {};
  if (!gbuffer.worldPosition || !gbuffer.worldNormal)
    throw std::invalid_argument("ReferenceTracer::visibility: G-buffer has no position or normal data");
  const int width = gbuffer.width;
  const int height = gbuffer.height;
  std::vector<float> result(static_cast<size_t>(width) * height, 0.0f);

  Light light = options.light ? *options.light : impl_->light;
  if (glm::length(light.direction) > 0.0f) light.direction = glm::normalize(light.direction);
  int gridSize = 0;  // 0 = hard shadows, one ray per pixel
  if (light.radius > 0.0f)
    gridSize = std::max(1, static_cast<int>(std::lround(std::sqrt(std::max(1, options.lightSamples)))));

  // Rows are handed out dynamically (shadowed regions cost more); each pixel's result depends
  // only on its own inputs, so the split cannot change the output.
  std::atomic<int> nextRow{0};
  auto worker = [&]() {
    for (int y = nextRow++; y < height; y = nextRow++) {
      for (int x = 0; x < width; ++x) {
        const size_t pixel = static_cast<size_t>(y) * width + x;
        const float* pos = gbuffer.worldPosition + 4 * pixel;
        if (!(pos[3] > 0.5f)) continue;  // background stays 0
        const float* nrm = gbuffer.worldNormal + 4 * pixel;
        const uint32_t* id = gbuffer.surface ? gbuffer.surface + 4 * pixel : nullptr;
        const int instance = id && id[0] > 0 ? static_cast<int>(id[0] - 1) : -1;
        const int triangle = id && id[0] > 0 ? static_cast<int>(id[1]) : -1;
        result[pixel] = impl_->shade(light, glm::vec3(pos[0], pos[1], pos[2]), glm::vec3(nrm[0], nrm[1], nrm[2]),
                                     instance, triangle, gridSize, pixel);
      }
    }
  };
  int threads = options.threads > 0 ? options.threads : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::clamp(threads, 1, std::max(1, height));
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& t : pool) t.join();
  return result;
}

bool ReferenceTracer::pointLit(const glm::vec3& p, const glm::vec3& n, int instance, int triangle) const {
  // Hard visibility toward the light's centre, with the same ray start and tests as visibility().
  return impl_->shade(impl_->light, p, n, instance, triangle, 0, 0) > 0.5f;
}

}  // namespace sl

namespace sl {

float ReferenceTracer::transmittanceToLight(const glm::vec3& p) const {
  glm::vec3 toLight;
  float distance;
  if (!isFinite(p) || !impl_->centreToLight(impl_->light, p, toLight, distance)) return 0.0f;
  RayStart start;
  start.origin = p;
  start.tolerance = std::max(kPlaneTolerance * maxAbs(glm::dvec3(p)), kMinTolerance);
  const float tfar = impl_->light.type == Light::Type::Directional ? distance : distance * (1.0f - 1e-4f);
  return impl_->transmittance(start, toLight, tfar);
}

}  // namespace sl
