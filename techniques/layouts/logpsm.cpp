// The LogPSM layout (see logpsm.h).
#include "layouts/logpsm.h"

#include "part/light_frame.h"
#include "layouts/lispsm.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <mutex>

namespace sl {

namespace {

constexpr int kMaxTessLevel = 64;  // GL_MAX_TESS_GEN_LEVEL is at least 64

// The longest edge of any triangle in world units (instances' scales included), cached per
// scene generation (LayoutInput::sceneGeneration; 0 = not cached): it decides how fine the
// tessellation must be, hence how strong the warp may be. (It was keyed on the scene's address
// and triangle count, which a scene loaded where another one lived could share.)
float longestCasterEdge(const Scene& scene, uint64_t generation) {
  static std::mutex mutex;
  static uint64_t cachedGeneration = 0;
  static float cachedEdge = 0.0f;
  std::lock_guard<std::mutex> lock(mutex);
  if (generation != 0 && generation == cachedGeneration) return cachedEdge;
  std::vector<float> meshEdge(scene.meshes.size(), 0.0f);
  for (size_t k = 0; k < scene.meshes.size(); ++k) {
    const Mesh& m = scene.meshes[k];
    for (size_t i = 0; i + 2 < m.indices.size(); i += 3)
      for (int e = 0; e < 3; ++e)
        if (m.indices[i + e] < m.positions.size() && m.indices[i + (e + 1) % 3] < m.positions.size())
          meshEdge[k] = std::max(meshEdge[k],
                                 glm::length(m.positions[m.indices[i + e]] - m.positions[m.indices[i + (e + 1) % 3]]));
  }
  float edge = 0.0f;
  for (const Instance& inst : scene.instances) {
    if (inst.mesh < 0 || size_t(inst.mesh) >= meshEdge.size()) continue;  // as Scene::boundsAt
    const glm::mat4 t = inst.transformAt(0.0);
    const float scale =
        std::max({glm::length(glm::vec3(t[0])), glm::length(glm::vec3(t[1])), glm::length(glm::vec3(t[2]))});
    edge = std::max(edge, meshEdge[size_t(inst.mesh)] * scale);
  }
  if (generation != 0) cachedGeneration = generation, cachedEdge = edge;
  return edge;
}

}  // namespace

// Linear interpolation of u(t) over [0, h] errs by at most h^2 max|u''| / 8, with
// |u''| = 1 / (C (δ + t)^2) largest at t = 0 and C = ln(1 + 1/δ); u in [0, 1] spans `size` texels.
float logChordErrorTexels(float delta, float span, int segments, int size) {
  const double h = double(span) / std::max(segments, 1), c = std::log1p(1.0 / delta);
  return float(double(size) * h * h / (8.0 * c * double(delta) * delta));
}

float logDeltaForError(float span, float maxErrorTexels, int size) {
  double lo = 1e-6, hi = kNoWarpDelta;  // the error falls as δ grows: bisect in log space
  for (int i = 0; i < 80; ++i) {
    const double mid = std::sqrt(lo * hi);
    (logChordErrorTexels(float(mid), span, kMaxTessLevel, size) > maxErrorTexels ? lo : hi) = mid;
  }
  return float(hi);
}

namespace {

struct LogFit {
  LightSpace space;
  float delta = 0.0f, deltaView = 0.0f, deltaBudget = 0.0f, span = 0.0f, errorTexels = 0.0f;
  bool tessellated = true, perspective = false;
};

// Lloyd et al.'s perspective part: x divided by the distance from the logarithm's pole, so a
// texel narrows toward the viewer across the view too (the log already does it along). Clip
// coordinates, in the light view (x, y along the view, z toward the light):
//   W = (y - c_y) / (lo_y - c_y)      1 at the window's near side, 1 + 1/δ at its far side;
//   Y = 2 (y - lo_y) / extent_y - 1   linear and not divided: the log warp maps it and scales by W
//                                     (layouts/single_matrix.glsl, lightViewClip);
//   X, Z: (x - eye_x) / W and z / W fitted to [-1, 1] over the body's corners (a projective map
//         takes its extremes there; z only clips, depth is written per fragment).
// The pole c_y = lo_y - δ extent_y is the log's, so both axes follow 1/(distance from it).
glm::mat4 logPerspectiveProjection(const LightViewBox& box, const FocusBody& body, const glm::mat4& lightView,
                                   float eyeX, float delta, glm::vec2 jitterTexels, float& texelWorldSize) {
  const glm::vec3 extent = glm::max(box.hi - box.lo, glm::vec3(1e-4f));
  const float poleY = box.lo.y - delta * extent.y;
  const float wScale = 1.0f / (box.lo.y - poleY);
  glm::vec2 uRange(1e30f, -1e30f), vRange(1e30f, -1e30f);
  for (const auto& p : body.receivers) {
    const glm::vec3 q(lightView * glm::vec4(p, 1.0f));
    const float w = std::max((q.y - poleY) * wScale, 1e-6f);
    uRange = glm::vec2(std::min(uRange.x, (q.x - eyeX) / w), std::max(uRange.y, (q.x - eyeX) / w));
    for (float z : {box.zMin, box.zMax}) vRange = glm::vec2(std::min(vRange.x, z / w), std::max(vRange.y, z / w));
  }
  const float uSpan = std::max(uRange.y - uRange.x, 1e-6f);
  uRange += jitterTexels.x * uSpan / float(std::max(body.size, 1));
  const float vMargin = std::max(1e-4f, (vRange.y - vRange.x) * 1e-3f);
  vRange += glm::vec2(-vMargin, vMargin);
  glm::mat4 m(0.0f);  // m[column][row]; columns multiply light-view x, y, z, 1
  m[1][3] = wScale, m[3][3] = -poleY * wScale;
  const float jitterY = jitterTexels.y / float(std::max(body.size, 1));
  m[1][1] = 2.0f / extent.y, m[3][1] = -2.0f * (box.lo.y / extent.y + jitterY) - 1.0f;
  const float ax = 2.0f / uSpan, bx = -2.0f * uRange.x / uSpan - 1.0f;  // X = ax (x - eyeX) + bx W
  m[0][0] = ax, m[1][0] = bx * m[1][3], m[3][0] = -ax * eyeX + bx * m[3][3];
  const float az = 2.0f / (vRange.y - vRange.x), bz = -2.0f * vRange.x / (vRange.y - vRange.x) - 1.0f;
  m[2][2] = az, m[1][2] = bz * m[1][3], m[3][2] = bz * m[3][3];
  texelWorldSize = uSpan / float(std::max(body.size, 1));  // at the near side (W = 1)
  return m;
}

// The orthographic window around the receivers in the view-aligned light basis, casters along
// the light, and δ from the viewer's distance to the window's near side.
LogFit logFit(const LayoutInput& in) {
  const FocusBody body = focusBody(in);
  const Light light = layoutLight(in);
  LogFit fit;
  if (light.type == Light::Type::Spot) {  // the paper's warp for spot lights is not done here
    fit.space = focusedMap(in, body);
    return fit;
  }
  const glm::mat4 invView = glm::inverse(in.cameraView);
  const glm::vec3 eye(invView[3]), viewDir = -glm::normalize(glm::vec3(invView[2]));
  const float cosGamma = glm::dot(viewDir, glm::normalize(light.direction));
  const float sinGamma = std::sqrt(std::max(0.0f, 1.0f - cosGamma * cosGamma));
  // As LiSPSM's: near a view along the light δ grows to "no warp" and the basis turns to the fixed one.
  const float w = viewWarpWeight(sinGamma);
  const glm::mat4 lightView = warpBasis(light, eye, viewDir, cosGamma, w, in.jitter.rotationRad);
  const LightViewBox box = lightViewBox(lightView, body.receivers, body.casters);
  const glm::vec3 lo = box.lo, hi = box.hi;
  float zn = 1e30f;
  for (const auto& p : body.receivers) zn = std::min(zn, glm::dot(p - eye, viewDir));
  const glm::vec2 extent = glm::max(glm::vec2(hi - lo), glm::vec2(1e-4f));
  const glm::vec2 jitter = in.jitter.offsetTexels * extent / float(body.size);
  LightView v;
  v.perspective = true;  // warped: depth written per fragment, texel sizes measured by the shaders
  v.view = lightView;
  v.windowMin = glm::vec2(lo) + jitter;
  v.windowMax = glm::vec2(hi) + jitter;
  const float margin = std::max(1e-3f, (box.zMax - box.zMin) * 1e-3f);
  v.nearPlane = -box.zMax - margin;
  v.farPlane = -box.zMin + margin;
  v.proj = glm::ortho(v.windowMin.x, v.windowMax.x, v.windowMin.y, v.windowMax.y, v.nearPlane, v.farPlane);
  v.texelWorldSize = extent.x / float(body.size);  // at the near side; shaders measure the rest

  // The viewer sits (lo.y - eye's y) before the window's near side, plus z_n sin(gamma) for the
  // near plane; the logarithm's pole goes that far before t = 0, so u ~ ln(view distance).
  const glm::vec3 eyeLight(lightView * glm::vec4(eye, 1.0f));
  const float distance = std::max(lo.y - eyeLight.y, 0.0f) + std::max(zn, 1e-3f) * std::max(sinGamma, 1e-3f);
  fit.deltaView = in.params->f("logpsm.delta_scale") * distance / extent.y / std::max(w, 1e-6f);
  fit.span = std::min(longestCasterEdge(*in.scene, in.sceneGeneration) / extent.y, 1.0f);
  fit.deltaBudget = logDeltaForError(fit.span, in.params->f("logpsm.max_error"), body.size);
  fit.delta = std::max(fit.deltaView, fit.deltaBudget);
  if (!std::isfinite(fit.delta)) fit.delta = kNoWarpDelta;  // a degenerate body: no warp rather than NaN
  v.logDelta = fit.delta >= kNoWarpDelta ? 0.0f : fit.delta;
  fit.perspective = v.logDelta > 0.0f && in.params->b("logpsm.perspective");
  if (fit.perspective)
    v.proj =
        logPerspectiveProjection(box, body, lightView, eyeLight.x, fit.delta, in.jitter.offsetTexels, v.texelWorldSize);
  v.viewProj = v.proj * v.view;
  fit.tessellated = in.params->b("logpsm.tessellate");
  fit.errorTexels = v.logDelta > 0.0f
                        ? logChordErrorTexels(fit.delta, fit.span, fit.tessellated ? kMaxTessLevel : 1, body.size)
                        : 0.0f;
  fit.space = LightSpace::single(v, body.size);
  return fit;
}

// Every view of this layout goes through the warp (δ = 0: the identity), so casters are tessellated;
// except a spot light's focused map: the warp stage assumes the orthographic basis, and drawing
// a spot's perspective view through it misplaced every caster (13 % of spotlight's pixels wrong).
LogFit logFitWarped(const LayoutInput& in) {
  LogFit fit = logFit(in);
  if (layoutLight(in).type == Light::Type::Spot) return fit;
  for (LightView& v : fit.space.views) {
    v.projection = LightView::Projection::LogWarp;
    v.sortCasters = in.params->b("logpsm.sort_casters");
  }
  return fit;
}

class LogPsmState : public LayoutState {
 public:
  using LayoutState::LayoutState;
  LightSpace compute(const LayoutInput& in) override {
    fit_ = logFitWarped(in);
    return fit_.space;
  }
  std::string status() const override {
    if (fit_.delta <= 0.0f) return "logpsm: spot light, focused map (no warp)";
    char text[300];
    // Tessellated, only the edges are cut into chords: interiors are one fan whose fragments
    // solve depth and coverage from their triangle (shaders/passes/warp_caster.glsl).
    std::snprintf(
        text, sizeof text, "delta %.3g (%s); texel density near/far %.1fx; %s <= %.2f texels%s%s", double(fit_.delta),
        fit_.deltaBudget > fit_.deltaView ? "limited by the error budget" : "viewer", double(1.0f + 1.0f / fit_.delta),
        fit_.tessellated ? "chords along the view" : "untessellated edges (tessellate off)", double(fit_.errorTexels),
        fit_.perspective && fit_.tessellated ? "; across it (perspective part) per edge, up to 64 pieces" : "",
        fit_.tessellated ? "; a cut patch's interior solved per fragment" : "");
    return text;
  }

 private:
  LogFit fit_;
};

class LogPsmLayout : public Layout {
 public:
  std::string id() const override { return "logpsm"; }
  std::string help() const override {
    return "logarithmic warp along the projected view direction (after Lloyd et al. 2008), casters tessellated "
           "so the bent edges are drawn as chords within an error budget";
  }
  std::string glslModule() const override { return "layouts/logpsm.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {{.key = "logpsm.delta_scale",
             .type = ParamType::Float,
             .min = 0.05,
             .max = 100,
             .defaultValue = 1,
             .unit = "x",
             .help = "the logarithm's offset δ as a multiple of the viewer's distance to the map (small = stronger "
                     "warp, more texels near the viewer; large = towards a uniform map)",
             .logScale = true},
            {.key = "logpsm.max_error",
             .type = ParamType::Float,
             .min = 0.05,
             .max = 16,
             .defaultValue = 0.5,
             .unit = "texels",
             .help = "largest distance between a tessellated caster edge and the true warped curve; the warp is "
                     "weakened until the scene's longest edge meets it at the largest tessellation level",
             .logScale = true},
            {.key = "logpsm.perspective",
             .type = ParamType::Bool,
             .defaultValue = 1,
             .help = "Lloyd et al.'s perspective part: x divided by the distance from the log's pole, so texels "
                     "also narrow across the view near the viewer (wins on wide far fields such as terrain; its "
                     "tessellation costs about 2x on a software rasterizer, little on a GPU; off: the log warp "
                     "of y alone)"},
            {.key = "logpsm.tessellate",
             .type = ParamType::Bool,
             .defaultValue = 1,
             .help = "subdivide casters before warping them (off: each triangle drawn straight between its warped "
                     "corners, as a plain rasterizer would: bent shadow edges, for teaching)"},
            {.key = "logpsm.sort_casters",
             .type = ParamType::Bool,
             .defaultValue = 1,
             .help = "draw the casters none of whose edges need pieces without the tessellation stages: a compute "
                     "pass sorts each instance's triangles every frame (same map; a software tessellator runs per "
                     "patch whatever its levels)"}};
  }
  LightSpace compute(const LayoutInput& in) const override { return logFitWarped(in).space; }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<LogPsmState>(*this); }
};

}  // namespace

void registerLogLayouts(std::vector<std::unique_ptr<Layout>>& out) { out.push_back(std::make_unique<LogPsmLayout>()); }

}  // namespace sl
