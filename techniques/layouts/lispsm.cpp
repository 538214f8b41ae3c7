// Light space perspective shadow maps (Wimmer, Scherzer, Purgathofer, EGSR 2004): a perspective
// warp whose axis is the view direction projected onto the light's image plane, so texels are
// denser near the viewer, with the free parameter n chosen to even out the aliasing error
// (n_opt = (z_n + sqrt(z_f z_n)) / sin(gamma)). Directional lights only; a spot light, or a view
// looking (anti)parallel to the light (dueling frusta: no warp helps), falls back to focusing.
#include "layouts/lispsm.h"

#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// Below kFallbackSinGamma the warp degenerates (n -> infinity): the focused map is the same.
// Between it and kFullWarpSinGamma n grows smoothly to infinity and the warp axis turns to the
// fixed light basis, so the map does not pop when the view turns toward the light (beyond the
// paper, which switches at once).
constexpr float kFallbackSinGamma = 0.05f, kFullWarpSinGamma = 0.15f;
// n is capped at this many body depths: the warp is then within ~d/n of orthographic (about a
// texel at 1024²), which is what the fallback's focused map is.
constexpr float kMaxNOverD = 1000.0f;

// The warp and its fit, in the light view whose +y is the projected view direction: receivers
// span [lo, hi] there, casters [zLightMin, zLightMax] along the light.
LightView warpedView(const glm::mat4& lightView, const glm::vec3& eye, float sinGamma, const glm::vec3& viewDir,
                     const std::vector<glm::vec3>& receivers, glm::vec3 lo, glm::vec3 hi, float zLightMin,
                     float zLightMax, const LispsmN& nChoice, float warpWeight, int size, const LayoutJitter& jitter) {
  // n_opt (Wimmer et al. 2004, general case): z_n is the view-space distance to the body's near
  // side, d the body's extent along the warp axis, z_f = z_n + d sin(gamma).
  float zn = 1e30f;
  for (const auto& p : receivers) zn = std::min(zn, glm::dot(p - eye, viewDir));
  zn = std::max(zn, 1e-3f);
  const float d = std::max(hi.y - lo.y, 1e-4f);
  const float znLight = zn / sinGamma;
  const float zfLight = znLight + d * sinGamma;
  const float nOpt = (znLight + std::sqrt(zfLight * znLight)) / sinGamma;
  // The survey's endpoints of the free parameter: n = z_n (PSM-like), n_opt, n -> infinity.
  const float nBase = nChoice.mode == LispsmN::Mode::ZNear ? znLight : nOpt;
  const float n = std::clamp(nBase * nChoice.scale / warpWeight, 1e-4f, kMaxNOverD * d);
  const float f = n + d;

  // Projection centre: the eye's lateral position, n behind the body's near side on the warp
  // axis; the perspective looks along +y: (x, y, z) -> (x, a y + b, z, y).
  const glm::vec3 eyeLight = glm::vec3(lightView * glm::vec4(eye, 1.0f));
  const glm::vec3 centre(eyeLight.x, lo.y - n, 0.0f);
  glm::mat4 warp(0.0f);
  warp[0][0] = 1.0f;
  warp[1][1] = (f + n) / (f - n);
  warp[3][1] = -2.0f * f * n / (f - n);
  warp[2][2] = 1.0f;
  warp[1][3] = 1.0f;
  const glm::mat4 toCentre = glm::translate(glm::mat4(1.0f), -centre);
  const glm::mat4 warpFromView = warp * toCentre;

  // Fit the unit cube to the warped receivers; depth covers every caster along their rays.
  glm::vec3 wlo(1e30f), whi(-1e30f);
  auto addWarped = [&](const glm::vec3& q) {
    glm::vec4 c = warpFromView * glm::vec4(q, 1.0f);
    glm::vec3 v = glm::vec3(c) / c.w;
    wlo = glm::min(wlo, v);
    whi = glm::max(whi, v);
  };
  for (const auto& p : receivers) {
    glm::vec3 q = glm::vec3(lightView * glm::vec4(p, 1.0f));
    addWarped(glm::vec3(q.x, q.y, zLightMin));
    addWarped(glm::vec3(q.x, q.y, zLightMax));
  }
  if (warpWeight < 1.0f) {
    // Toward the fallback the window turns into the focused map's: square in light units and
    // centred (a post-warp x' is x / (distance from the centre), y' spans 2 over d), never
    // smaller than the fit, so the receivers stay covered.
    const float side = std::max(hi.x - lo.x, d);
    const glm::vec2 square(0.5f * side / (n + 0.5f * d), side / d);
    const glm::vec2 centre = 0.5f * glm::vec2(wlo + whi), half = 0.5f * glm::vec2(whi - wlo);
    const glm::vec2 grown = glm::max(half, glm::mix(square, half, warpWeight));
    wlo = glm::vec3(centre - grown, wlo.z);
    whi = glm::vec3(centre + grown, whi.z);
  }
  glm::vec2 extent = glm::max(glm::vec2(whi - wlo), glm::vec2(1e-6f));
  glm::vec2 offset = jitter.offsetTexels * extent / static_cast<float>(size);
  wlo += glm::vec3(offset, 0.0f);
  whi += glm::vec3(offset, 0.0f);
  const float zMargin = std::max(1e-4f, (whi.z - wlo.z) * 1e-3f);
  glm::mat4 fit = glm::ortho(wlo.x, whi.x, wlo.y, whi.y, -(whi.z + zMargin), -(wlo.z - zMargin));

  LightView ls;
  ls.perspective = true;  // warped: stored depth is written per fragment, linear in light-view z
  ls.view = lightView;
  ls.proj = fit * warpFromView;
  ls.viewProj = ls.proj * ls.view;
  const float depthMargin = std::max(1e-3f, (zLightMax - zLightMin) * 1e-3f);
  ls.nearPlane = -zLightMax - depthMargin;
  ls.farPlane = -zLightMin + depthMargin;
  ls.windowMin = glm::vec2(wlo);
  ls.windowMax = glm::vec2(whi);
  // Texel sizes vary over a warped map; shaders measure them from the projection. This is the
  // size at the body's near side, for display.
  ls.texelWorldSize = (hi.x - lo.x) / static_cast<float>(size);
  return ls;
}

// Near the fallback the warped map turns into the unsnapped focused map (w -> 0). With
// layout.snap the fallback is the snapped one, so the warped map is carried the same way: the
// affine map from the unsnapped focused window to the snapped one, weighted by 1 - w, applied
// after the warp. It is the identity at w = 1 and gives the snapped map at w = 0, so the map stays
// continuous; both windows hold the receivers, and so does every blend of them.
void snapTowardFallback(LightView& warped, const LightView& unsnapped, const LightView& snapped, float w) {
  const glm::mat4 toSnapped = snapped.proj * glm::inverse(unsnapped.proj);
  glm::mat4 blend;
  for (int c = 0; c < 4; ++c) blend[c] = glm::mix(toSnapped[c], glm::mat4(1.0f)[c], w);
  warped.proj = blend * warped.proj;
  warped.viewProj = warped.proj * warped.view;
}

}  // namespace

glm::mat4 warpBasis(const Light& light, const glm::vec3& eye, const glm::vec3& viewDir, float cosGamma, float w,
                    float roll) {
  const glm::vec3 L = glm::normalize(light.direction);
  const glm::vec3 projected = viewDir - L * cosGamma;
  // Looking straight along the light the view has no direction on the light's plane (w is 0
  // there): the fixed basis, not normalize(0) = NaN.
  glm::vec3 up = glm::length(projected) > 1e-6f ? glm::normalize(projected) : glm::vec3(0.0f);
  if (up == glm::vec3(0.0f)) w = 0.0f;
  if (w < 1.0f) {
    const glm::mat4 fixed = lightViewMatrix(light, 0.0f);
    const glm::vec3 fixedUp(fixed[0][1], fixed[1][1], fixed[2][1]);
    const float angle = w > 0.0f ? std::atan2(glm::dot(glm::cross(fixedUp, up), L), glm::dot(fixedUp, up)) : 0.0f;
    up = glm::vec3(glm::rotate(glm::mat4(1.0f), angle * w, L) * glm::vec4(fixedUp, 0.0f));
  }
  glm::mat4 lightView = glm::lookAt(eye, eye + L, up);
  if (roll != 0.0f) lightView = glm::rotate(glm::mat4(1.0f), roll, glm::vec3(0, 0, 1)) * lightView;
  return lightView;
}

LightView lispsmView(const Light& light, const glm::mat4& cameraView, const std::vector<glm::vec3>& receivers,
                     const std::vector<glm::vec3>& casters, const LispsmN& nChoice, int size, bool snap,
                     const LayoutJitter& jitter) {
  const glm::mat4 invView = glm::inverse(cameraView);
  const glm::vec3 eye = glm::vec3(invView[3]);
  const glm::vec3 viewDir = -glm::normalize(glm::vec3(invView[2]));
  const float cosGamma = glm::dot(viewDir, glm::normalize(light.direction));
  const float sinGamma = std::sqrt(std::max(0.0f, 1.0f - cosGamma * cosGamma));
  auto focused = [&](bool snapped) {
    glm::mat4 view = lightViewMatrix(light, jitter.rotationRad);
    if (light.type == Light::Type::Spot)
      return fitPerspective(light, view, receivers, casters, size, true, snapped, jitter);
    return fitOrthographic(view, receivers, casters, size, snapped, jitter);
  };
  if (light.type == Light::Type::Spot || sinGamma < kFallbackSinGamma || nChoice.mode == LispsmN::Mode::Infinity)
    return focused(snap);
  const float w = viewWarpWeight(sinGamma);
  const glm::mat4 lightView = warpBasis(light, eye, viewDir, cosGamma, w, jitter.rotationRad);
  const LightViewBox box = lightViewBox(lightView, receivers, casters);
  LightView warped = warpedView(lightView, eye, sinGamma, viewDir, receivers, box.lo, box.hi, box.zMin, box.zMax,
                                nChoice, std::max(w, 1e-6f), size, jitter);
  if (snap && w < 1.0f) snapTowardFallback(warped, focused(false), focused(true), w);
  return warped;
}

float viewWarpWeight(float sinGamma) {
  const float t = std::clamp((sinGamma - kFallbackSinGamma) / (kFullWarpSinGamma - kFallbackSinGamma), 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);  // smoothstep: no kink where the warp sets in
}

LightViewBox lightViewBox(const glm::mat4& lightView, const std::vector<glm::vec3>& receivers,
                          const std::vector<glm::vec3>& casters) {
  LightViewBox box;
  for (const auto& p : receivers) {
    const glm::vec3 q(lightView * glm::vec4(p, 1.0f));
    box.lo = glm::min(box.lo, q);
    box.hi = glm::max(box.hi, q);
  }
  box.zMin = box.lo.z, box.zMax = box.hi.z;
  for (const auto& p : casters) {
    const float z = (lightView * glm::vec4(p, 1.0f)).z;
    box.zMin = std::min(box.zMin, z), box.zMax = std::max(box.zMax, z);
  }
  return box;
}

LispsmN lispsmN(const ParamSet& params) {
  LispsmN n;
  n.scale = params.f("lispsm.n_scale");
  n.mode = static_cast<LispsmN::Mode>(params.i("lispsm.n"));
  return n;
}

std::vector<ParamDecl> lispsmParams() {
  return {{.key = "lispsm.n",
           .type = ParamType::Enum,
           .defaultValue = 0,
           .help = "the warp's free parameter n (the survey's slider endpoints): n_opt (even aliasing error), z_n "
                   "(PSM-like: the projection centre at the eye's distance), infinity (no warp: the focused map)",
           .choices = {"n_opt", "z_n", "infinity"}},
          {.key = "lispsm.n_scale",
           .type = ParamType::Float,
           .min = 0.05,
           .max = 20,
           .defaultValue = 1,
           .unit = "x n",
           .help = "warp strength: the projection centre's distance as a multiple of the chosen n (small = strong "
                   "warp, more texels near the viewer; large = towards focused)",
           .logScale = true}};
}

namespace {

class LispsmLayout : public Layout {
 public:
  std::string id() const override { return "lispsm"; }
  std::string help() const override {
    return "light space perspective warp along the projected view direction, n = n_opt (Wimmer et al. 2004): "
           "more texels near the viewer";
  }
  std::string glslModule() const override { return "layouts/single_matrix.glsl"; }
  std::vector<ParamDecl> params() const override { return lispsmParams(); }

  LightSpace compute(const LayoutInput& in) const override {
    const Bounds bounds = in.scene->boundsAt(in.time);
    const int size = in.params->i("shadowmap.size");
    auto casters = boxCorners(bounds);
    auto receivers = clipFrustumToBox(in.cameraView, in.cameraProj, bounds);
    if (receivers.empty()) receivers = casters;
    return LightSpace::single(lispsmView(layoutLight(in), in.cameraView, receivers, casters, lispsmN(*in.params), size,
                                         in.params->b("layout.snap"), in.jitter),
                              size);
  }
};

}  // namespace

void registerWarpedLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<LispsmLayout>());
}

}  // namespace sl
