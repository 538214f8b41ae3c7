// Trapezoidal shadow maps (Martin & Tan, EGSR 2004): in the light's image plane, a trapezoid
// around the projected view frustum (top edge at the near side, base at the far side, sides
// through a centre of projection on the centre line) is mapped onto the square map by a 2D
// projective transform, with the centre placed so that the focus line (tsm.focus of the way
// into the visible depth range) lands at tsm.focus_share of the map (the paper's 80 % rule).
// Directional lights; a spot light, or a view (anti)parallel to the light, gets the focused map.
#include "layouts/tsm.h"

#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace sl {

namespace {

using Quad = std::array<glm::dvec2, 4>;

// Heckbert 1989: the projective map taking the unit square (0,0) (1,0) (1,1) (0,1) to q.
glm::dmat3 squareToQuad(const Quad& q) {
  const double dx1 = q[1].x - q[2].x, dx2 = q[3].x - q[2].x, dy1 = q[1].y - q[2].y, dy2 = q[3].y - q[2].y;
  const double sx = q[0].x - q[1].x + q[2].x - q[3].x, sy = q[0].y - q[1].y + q[2].y - q[3].y;
  const double det = dx1 * dy2 - dx2 * dy1;
  const double g = (sx * dy2 - dx2 * sy) / det, h = (dx1 * sy - sx * dy1) / det;
  // Columns of the glm matrix: (u, v, 1) -> (x, y, w).
  return glm::dmat3(glm::dvec3(q[1].x - q[0].x + g * q[1].x, q[1].y - q[0].y + g * q[1].y, g),
                    glm::dvec3(q[3].x - q[0].x + h * q[3].x, q[3].y - q[0].y + h * q[3].y, h),
                    glm::dvec3(q[0].x, q[0].y, 1.0));
}

struct Trapezoid {
  Quad corners;  // to (0,0) (1,0) (1,1) (0,1) of the square: top edge (near the viewer) first
  bool valid = false;
};

// The trapezoid around `pts` (light-plane xy) with its centre line from `nearC` toward `farC`.
Trapezoid fitTrapezoid(const std::vector<glm::dvec2>& pts, glm::dvec2 nearC, glm::dvec2 farC, glm::dvec2 focusC,
                       double share) {
  Trapezoid t;
  glm::dvec2 u = farC - nearC;
  double extent = 0.0;
  for (const auto& p : pts) extent = std::max(extent, glm::length(p - nearC));
  // Looking along the light the centre line vanishes: no trapezoid helps (dueling frusta).
  if (glm::length(u) < 0.05 * extent || extent <= 0.0) return t;
  u = glm::normalize(u);
  const glm::dvec2 side(-u.y, u.x);
  double top = 1e300, base = -1e300;
  for (const auto& p : pts) {
    top = std::min(top, glm::dot(p - nearC, u));
    base = std::max(base, glm::dot(p - nearC, u));
  }
  const double lambda = std::max(base - top, 1e-9);
  // 80 % rule: the focus line at delta from the top maps to `share` of the map when the centre of
  // projection is eta behind the top: (eta + lambda) delta = share lambda (eta + delta).
  const double delta = std::clamp(glm::dot(focusC - nearC, u) - top, 1e-6 * lambda, share * lambda * 0.999);
  const double eta = (1.0 - share) * lambda * delta / (share * lambda - delta);
  const glm::dvec2 q = nearC + u * (top - eta);
  double lo = 1e300, hi = -1e300;  // slopes of the sides (offset along `side` per unit along u)
  for (const auto& p : pts) {
    const double along = glm::dot(p - q, u), across = glm::dot(p - q, side);
    lo = std::min(lo, across / along);
    hi = std::max(hi, across / along);
  }
  auto at = [&](double along, double slope) { return q + u * along + side * (along * slope); };
  // Map +x to -side so that (x, y) keep the light plane's orientation: a mirrored map turns
  // front faces into back faces, and the shadow pass culls by winding (it stored the far walls of
  // a box the camera stands in: 78 % wrong).
  t.corners = {at(eta, hi), at(eta, lo), at(eta + lambda, lo), at(eta + lambda, hi)};
  t.valid = std::isfinite(eta) && hi > lo;
  return t;
}

// The light view of a trapezoid: light-plane xy through the trapezoid-to-square map, clip z
// fitted so that no receiver or caster along their light rays is clipped (stored depth is
// light-view linear, written per fragment, so clip z only has to keep them).
LightView trapezoidView(const glm::mat4& lightView, const Trapezoid& trap, const std::vector<glm::dvec2>& pts,
                        float zLightMin, float zLightMax, int size, const LayoutJitter& jitter) {
  // quad -> unit square -> [-1, 1]², then the jitter in texels of the map.
  const glm::dmat3 toSquare = glm::inverse(squareToQuad(trap.corners));
  const glm::dvec2 shift = glm::dvec2(jitter.offsetTexels) * (2.0 / size);
  const glm::dmat3 toNdc(glm::dvec3(2, 0, 0), glm::dvec3(0, 2, 0), glm::dvec3(-1 + shift.x, -1 + shift.y, 1));
  const glm::dmat3 h = toNdc * toSquare;
  // z / w over every receiver point at both ends of the casters' light-view z range.
  double rLo = 1e300, rHi = -1e300;
  for (const auto& p : pts) {
    const double w = h[0][2] * p.x + h[1][2] * p.y + h[2][2];
    for (double z : {double(zLightMin), double(zLightMax)}) {
      rLo = std::min(rLo, z / w);
      rHi = std::max(rHi, z / w);
    }
  }
  const double margin = std::max((rHi - rLo) * 1e-3, 1e-9);
  const double a = 2.0 / (rHi - rLo + 2.0 * margin), b = -1.0 - a * (rLo - margin);
  glm::dmat4 m(0.0);  // columns: x, y, z, 1 of the light view -> clip
  for (int c = 0; c < 2; ++c) m[c] = glm::dvec4(h[c][0], h[c][1], b * h[c][2], h[c][2]);
  m[2] = glm::dvec4(0.0, 0.0, a, 0.0);
  m[3] = glm::dvec4(h[2][0], h[2][1], b * h[2][2], h[2][2]);
  LightView v;
  v.perspective = true;  // projective: stored depth is written per fragment, linear in light-view z
  v.view = lightView;
  v.proj = glm::mat4(m);
  v.viewProj = v.proj * v.view;
  const float depthMargin = std::max(1e-3f, (zLightMax - zLightMin) * 1e-3f);
  v.nearPlane = -zLightMax - depthMargin;
  v.farPlane = -zLightMin + depthMargin;
  // Texel sizes vary over the trapezoid; shaders measure them. This is the top edge's, for display.
  v.texelWorldSize = static_cast<float>(glm::length(trap.corners[1] - trap.corners[0])) / size;
  return v;
}

class TrapezoidalLayout : public Layout {
 public:
  std::string id() const override { return "tsm"; }
  std::string help() const override {
    return "trapezoidal shadow map (Martin & Tan 2004): the trapezoid around the view frustum in light space mapped "
           "to the square map, 80 % of it for the focus region";
  }
  std::string glslModule() const override { return "layouts/single_matrix.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {{.key = "tsm.focus",
             .type = ParamType::Float,
             .min = 0.01,
             .max = 1,
             .defaultValue = 0.3,
             .unit = "of depth",
             .help = "the focus region: this fraction of the visible view depth range, from its near end"},
            {.key = "tsm.focus_share",
             .type = ParamType::Float,
             .min = 0.5,
             .max = 0.95,
             .defaultValue = 0.8,
             .unit = "of map",
             .help = "share of the map's rows given to the focus region (the paper's 80 % rule)"}};
  }
  LightSpace compute(const LayoutInput& in) const override;
};

LightSpace TrapezoidalLayout::compute(const LayoutInput& in) const {
  const Light light = layoutLight(in);
  const FocusBody fb = focusBody(in);
  const int size = fb.size;
  const auto& casters = fb.casters;
  const auto& receivers = fb.receivers;
  const glm::mat4& lightView = fb.lightView;
  auto focused = [&] { return focusedMap(in, fb); };
  if (light.type == Light::Type::Spot) return focused();

  const glm::mat4 inv = glm::inverse(in.cameraView);
  const glm::vec3 eye(inv[3]), viewDir = -glm::normalize(glm::vec3(inv[2]));
  float zMin = 1e30f, zMax = -1e30f, lightMin = 1e30f, lightMax = -1e30f;
  std::vector<glm::dvec2> pts;
  for (const auto& p : receivers) {
    const float z = glm::dot(p - eye, viewDir);
    zMin = std::min(zMin, z);
    zMax = std::max(zMax, z);
    const glm::vec3 q = glm::vec3(lightView * glm::vec4(p, 1.0f));
    pts.emplace_back(q.x, q.y);
  }
  for (const auto& p : casters) {
    const float z = (lightView * glm::vec4(p, 1.0f)).z;
    lightMin = std::min(lightMin, z);
    lightMax = std::max(lightMax, z);
  }
  zMin = std::max(zMin, 0.0f);
  auto toPlane = [&](float depth) { return glm::dvec2(glm::vec2(lightView * glm::vec4(eye + viewDir * depth, 1.0f))); };
  const Trapezoid trap =
      fitTrapezoid(pts, toPlane(zMin), toPlane(zMax), toPlane(zMin + in.params->f("tsm.focus") * (zMax - zMin)),
                   in.params->f("tsm.focus_share"));
  if (!trap.valid) return focused();
  return LightSpace::single(trapezoidView(lightView, trap, pts, lightMin, lightMax, size, in.jitter), size);
}

}  // namespace

void registerTrapezoidalLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<TrapezoidalLayout>());
}

}  // namespace sl
