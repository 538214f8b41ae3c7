// Perspective shadow maps (Stamminger & Drettakis, SIGGRAPH 2002): the shadow map is made in the
// camera's post-perspective space, where near objects are large, so they get more texels. A
// directional light there becomes a point light (or stays directional when it is parallel to
// the image plane). The virtual camera is slid back along its axis until every caster that can
// shadow a visible receiver lies in front of it, and its near plane pushed out to psm.near_push
// of its far plane (PSM's z-distribution is uneven: most of the post-perspective depth range is
// spent right behind the near plane).
// Not implemented (falls back to the focused map): the inverted case, when the light's
// post-perspective position lies behind the viewer (light from behind the camera), and spot
// lights.
#include "layouts/psm.h"

#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// Where the ray from p toward the light (-L) leaves the box: casters of p lie on that segment.
glm::vec3 towardLightToBox(const glm::vec3& p, const glm::vec3& toLight, const Bounds& b) {
  float tMax = 1e30f;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(toLight[a]) < 1e-9f) continue;
    const float t = ((toLight[a] > 0.0f ? b.max[a] : b.min[a]) - p[a]) / toLight[a];
    tMax = std::min(tMax, std::max(t, 0.0f));
  }
  return p + toLight * (tMax < 1e29f ? tMax : 0.0f);
}

// The virtual camera: slid back by `slide`, frustum around `body` (in its view space), near
// plane at `pushRatio` of the far plane at least.
glm::mat4 virtualCamera(const glm::mat4& cameraView, const std::vector<glm::vec3>& body, float pushRatio,
                        const std::vector<glm::vec3>& scene) {
  float zMin = 1e30f, zMax = -1e30f, sceneMin = 1e30f;
  for (const auto& p : body) {
    zMin = std::min(zMin, -(cameraView * glm::vec4(p, 1.0f)).z);
    zMax = std::max(zMax, -(cameraView * glm::vec4(p, 1.0f)).z);
  }
  for (const auto& p : scene) sceneMin = std::min(sceneMin, -(cameraView * glm::vec4(p, 1.0f)).z);
  zMax = std::max(zMax, zMin + 1e-3f);
  // (zMin + s) >= r (zMax + s): every caster in front of the near plane, pushed to r of the far;
  // and the whole scene in front of the virtual eye, so that nothing behind it (negative w)
  // folds into the map through the projective light.
  const float slide =
      std::max({0.0f, (pushRatio * zMax - zMin) / (1.0f - pushRatio), 1e-3f * (zMax - zMin) - sceneMin});
  const glm::mat4 view = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -slide)) * cameraView;
  float tx = 1e-3f, ty = 1e-3f;
  for (const auto& p : body) {
    const glm::vec3 q = glm::vec3(view * glm::vec4(p, 1.0f));
    tx = std::max(tx, std::abs(q.x / q.z));
    ty = std::max(ty, std::abs(q.y / q.z));
  }
  const float n = std::max(zMin + slide, 1e-4f) * 0.999f, f = (zMax + slide) * 1.001f;
  return glm::frustum(-tx * n, tx * n, -ty * n, ty * n, n, f) * view;
}

}  // namespace

namespace {

// The light's projection in post-perspective space of `virt`, applied to world points: a point
// light at the image of the light's direction (or a parallel light when that image is at
// infinity), looking at the body; clip z fitted to the body. Stored depth is written per
// fragment (world light-view linear), so the order along the rays (reversed when the light is
// behind the viewer: the "inverted" case) does not matter. False when the light's image lies
// among the body's points (no frustum narrower than 160 degrees holds them).
bool postPerspectiveLight(const glm::mat4& virt, const glm::vec3& L, const std::vector<glm::vec3>& body, int size,
                          const LayoutJitter& jitter, glm::mat4& out) {
  std::vector<glm::vec3> pts;
  glm::vec3 c(0.0f);
  for (const auto& p : body) {
    const glm::vec4 h = virt * glm::vec4(p, 1.0f);
    pts.push_back(glm::vec3(h) / h.w);
    c += pts.back();
  }
  c /= static_cast<float>(pts.size());
  float radius = 0.0f;
  for (const auto& q : pts) radius = std::max(radius, glm::length(q - c));
  const glm::vec4 h = virt * glm::vec4(-L, 0.0f);  // the light's direction, seen by the virtual camera
  const bool parallel = std::abs(h.w) <= 1e-4f * glm::length(glm::vec3(h));
  const glm::vec3 eye = parallel ? c + glm::normalize(glm::vec3(h)) * (2.0f * radius + 1.0f) : glm::vec3(h) / h.w;
  const glm::vec3 axis = glm::normalize(c - eye);
  const glm::vec3 up = std::abs(axis.y) > 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  glm::mat4 view = glm::lookAt(eye, c, up);
  if (jitter.rotationRad != 0.0f) view = glm::rotate(glm::mat4(1.0f), jitter.rotationRad, glm::vec3(0, 0, 1)) * view;
  glm::vec2 lo(1e30f), hi(-1e30f);
  float zNear = 1e30f, zFar = -1e30f;
  for (const auto& q : pts) {
    const glm::vec3 v = glm::vec3(view * glm::vec4(q, 1.0f));
    if (!parallel && -v.z <= 1e-6f) return false;
    const glm::vec2 xy = parallel ? glm::vec2(v) : glm::vec2(v) / -v.z;
    lo = glm::min(lo, xy);
    hi = glm::max(hi, xy);
    zNear = std::min(zNear, -v.z);
    zFar = std::max(zFar, -v.z);
  }
  if (!parallel && std::max({-lo.x, -lo.y, hi.x, hi.y}) > 5.6f) return false;  // tan 80 degrees
  glm::mat4 proj;
  if (parallel) {
    const float margin = std::max((zFar - zNear) * 1e-3f, 1e-5f);
    proj = glm::ortho(lo.x, hi.x, lo.y, hi.y, zNear - margin, zFar + margin);
  } else {
    const float n = zNear * 0.999f, f = zFar * 1.001f;
    proj = glm::frustum(lo.x * n, hi.x * n, lo.y * n, hi.y * n, n, f);
  }
  // Sub-texel jitter (pixel-correct) moves the map by texels of its own.
  const glm::vec2 shift = jitter.offsetTexels * (2.0f / static_cast<float>(size));
  out = glm::translate(glm::mat4(1.0f), glm::vec3(shift, 0.0f)) * proj * view * virt;
  return true;
}

// The post-perspective space is left-handed and the inverted case turns it over once more: a
// mirrored map turns front faces into back faces for the shadow pass's culling. Mirrors x back
// when a small triangle in the light's plane at `at` changes its winding.
glm::mat4 keepOrientation(const glm::mat4& m, const glm::mat4& lightView, const glm::vec3& at) {
  const glm::mat4 inv = glm::inverse(lightView);
  const glm::vec3 o = glm::vec3(lightView * glm::vec4(at, 1.0f));
  auto mapped = [&](float dx, float dy) {
    const glm::vec4 c = m * inv * glm::vec4(o + glm::vec3(dx, dy, 0.0f), 1.0f);
    return glm::vec2(c) / c.w;
  };
  const float h = 1e-2f * std::max(std::abs(o.z), 1.0f);
  const glm::vec2 a = mapped(0, 0), b = mapped(h, 0), c = mapped(0, h);
  const float winding = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  return winding < 0.0f ? glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)) * m : m;
}

class PerspectiveLayout : public Layout {
 public:
  std::string id() const override { return "psm"; }
  std::string help() const override {
    return "perspective shadow map (Stamminger & Drettakis 2002): the map made in the camera's post-perspective "
           "space, virtual camera slid back for casters behind the viewer, near plane pushed";
  }
  std::string glslModule() const override { return "layouts/single_matrix.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {{.key = "psm.near_push",
             .type = ParamType::Float,
             .min = 0.001,
             .max = 0.9,
             .defaultValue = 0.05,
             .unit = "of far",
             .help = "the virtual camera's near plane is pushed (the camera slid back) until it lies at this fraction "
                     "of its far plane: larger = a more even depth distribution, less warp",
             .logScale = true}};
  }
  LightSpace compute(const LayoutInput& in) const override;
};

LightSpace PerspectiveLayout::compute(const LayoutInput& in) const {
  const Light light = layoutLight(in);
  const FocusBody fb = focusBody(in);
  const Bounds& bounds = fb.bounds;
  const int size = fb.size;
  const auto& casters = fb.casters;
  const auto& receivers = fb.receivers;
  const glm::mat4& lightView = fb.lightView;
  auto focused = [&] { return focusedMap(in, fb); };
  if (light.type == Light::Type::Spot) return focused();
  // The body: visible receivers and, toward the light, where their casters can be.
  const glm::vec3 L = glm::normalize(light.direction);
  std::vector<glm::vec3> body = receivers;
  for (const auto& p : receivers) body.push_back(towardLightToBox(p, -L, bounds));
  const glm::mat4 virt = virtualCamera(in.cameraView, body, in.params->f("psm.near_push"), casters);
  glm::mat4 m;
  if (!postPerspectiveLight(virt, L, body, size, in.jitter, m)) return focused();
  m = keepOrientation(m, lightView, bounds.center());
  LightView v;
  v.perspective = true;  // projective: stored depth is written per fragment, linear in light-view z
  v.view = lightView;
  v.viewProj = m;
  v.proj = m * glm::inverse(lightView);
  float zNear = 1e30f, zFar = -1e30f;
  for (const auto& p : body) {
    const float z = -(lightView * glm::vec4(p, 1.0f)).z;
    zNear = std::min(zNear, z);
    zFar = std::max(zFar, z);
  }
  const float margin = std::max(1e-3f, (zFar - zNear) * 1e-3f);
  v.nearPlane = zNear - margin;
  v.farPlane = zFar + margin;
  v.texelWorldSize = (zFar - zNear) / size;  // for display; shaders measure the real one
  return LightSpace::single(v, size);
}

}  // namespace

void registerPerspectiveLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<PerspectiveLayout>());
}

}  // namespace sl
