#include "point/dual_paraboloid.h"

#include "part/light_frame.h"
#include "point/point_layout.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace sl {

namespace {

constexpr float kMaxZoom = 64.0f;

// Whether the directions lie within one closed hemisphere: the drawn one's (their view frame's
// -z; the receivers were clipped to it) or a cap of less than 90 degrees around their mean.
// Then what lies between them is bounded by great-circle arcs between pairs of them.
bool withinOneHemisphere(const std::vector<glm::vec3>& dirs, const glm::vec3& mean) {
  bool drawnSide = true;
  float minCos = 1.0f;
  for (const glm::vec3& d : dirs) {
    drawnSide = drawnSide && d.z <= 1e-5f;
    minCos = std::min(minCos, glm::dot(d, mean));
  }
  return drawnSide || minCos > std::cos(glm::radians(89.0f));
}

// The box (min, max corners, map units) around the image of every direction between `dirs`:
// what lies between them on the sphere is bounded by great-circle arcs between pairs of them, so
// the box around the images of every pair's arc (sampled finely: an arc's image is a circle arc)
// holds it. A handful of receivers' corners make a few hundred short arcs.
void arcsImageBox(const std::vector<glm::vec3>& dirs, glm::vec2& lo, glm::vec2& hi) {
  constexpr int kPieces = 32;
  lo = glm::vec2(1e30f);
  hi = glm::vec2(-1e30f);
  for (size_t i = 0; i < dirs.size(); ++i)
    for (size_t j = i; j < dirs.size(); ++j)
      for (int k = 0; k <= (i == j ? 0 : kPieces); ++k) {
        const glm::vec3 m = glm::mix(dirs[i], dirs[j], float(k) / kPieces);
        if (!(glm::length(m) > 1e-3f)) {  // opposite directions: no one arc between them
          lo = glm::vec2(-1.0f);
          hi = glm::vec2(1.0f);
          return;
        }
        const glm::vec2 image = paraboloidDiskImage(glm::normalize(m));
        lo = glm::min(lo, image);
        hi = glm::max(hi, image);
      }
}

}  // namespace

glm::vec4 fitParaboloidWindow(const std::vector<glm::vec3>& dirs, int size, bool snap) {
  const glm::vec4 whole(0.0f, 0.0f, 1.0f, 1.0f);
  glm::vec3 sum(0.0f);
  for (const glm::vec3& d : dirs) sum += d;
  if (dirs.empty() || !(glm::length(sum) > 1e-6f)) return whole;
  if (!withinOneHemisphere(dirs, glm::normalize(sum))) return whole;
  glm::vec2 lo, hi;
  arcsImageBox(dirs, lo, hi);
  return paraboloidWindowAround(lo, hi, size, snap, true);
}

namespace {

// The zoom of the window along an axis where the box spans `side`: 5 % on each side, then 4
// texels of the map this zoom makes: side' = 1.1 side + 8 texels of 2 / (zoom size) with
// zoom = 2 / side'. 0 where it would not magnify (the whole disk along that axis).
float windowZoom(float side, int size, bool snap) {
  const float texelsLeft = 1.0f - 8.0f / float(std::max(size, 16));
  float zoom = 2.0f * texelsLeft / (1.1f * side);
  if (!(zoom > 1.0f)) return 0.0f;  // NaN too
  zoom = std::min(zoom, kMaxZoom);
  return snap ? std::max(1.0f, std::exp2(std::floor(std::log2(zoom) * 4.0f) / 4.0f)) : zoom;
}

}  // namespace

glm::vec4 paraboloidWindowAround(glm::vec2 lo, glm::vec2 hi, int size, bool snap, bool square) {
  const glm::vec4 whole(0.0f, 0.0f, 1.0f, 1.0f);
  lo = glm::max(lo, glm::vec2(-1.0f));
  hi = glm::min(hi, glm::vec2(1.0f));
  if (!(lo.x <= hi.x && lo.y <= hi.y)) return whole;
  glm::vec2 side = hi - lo;
  if (square) side = glm::vec2(std::max(side.x, side.y));
  glm::vec2 zoom(windowZoom(side.x, size, snap), windowZoom(side.y, size, snap));
  if (zoom.x == 0.0f && zoom.y == 0.0f) return whole;
  glm::vec2 centre = 0.5f * (lo + hi);
  for (int a = 0; a < 2; ++a)
    if (zoom[a] == 0.0f) {  // that axis whole
      zoom[a] = 1.0f;
      centre[a] = 0.0f;
    }
  if (snap) {
    const glm::vec2 texel = 2.0f / (zoom * float(size));
    centre = glm::round(centre / texel) * texel;
  }
  return {centre, zoom};
}

FaceViews paraboloidViews(const Light& light, const LayoutInput& in, const std::vector<ViewPixelBounds>* seen) {
  const Bounds bounds = in.scene->boundsAt(in.time);
  const int size = in.params->i("shadowmap.size");
  const float far = pointLightFar(light, bounds);
  const float near = far * 1e-4f;  // as the cube's: linear depth, casters touching the light kept
  const std::vector<glm::vec3> box = boxCorners(bounds);
  std::vector<glm::vec4> frustum = frustumPlanes(in.cameraProj * in.cameraView);
  // Receivers beyond the light's reach are not lit: the fit need not hold them.
  const std::vector<glm::vec4> reach = boxPlanes({light.position - glm::vec3(far), light.position + glm::vec3(far)});
  frustum.insert(frustum.end(), reach.begin(), reach.end());
  const bool fit = in.params->b("paraboloid.fit"), snap = in.params->b("layout.snap");
  FaceViews out;
  out.space.views.clear();
  out.space.size = size;
  const glm::vec3 axes[2] = {{0, -1, 0}, {0, 1, 0}}, ups[2] = {{0, 0, -1}, {0, 0, 1}};
  for (int h = 0; h < 2; ++h) {
    LightView v;
    v.view = glm::lookAt(light.position, light.position + axes[h], ups[h]);
    if (in.jitter.rotationRad != 0.0f)  // the disk turns about its axis; the hemisphere is the same
      v.view = glm::rotate(glm::mat4(1.0f), in.jitter.rotationRad, glm::vec3(0, 0, 1)) * v.view;
    // viewProj is not how casters reach this view (lightViewClip is); a 160-degree frustum around
    // the axis stands for it where a matrix is drawn (the light-space debug view's box).
    v.proj = glm::perspective(glm::radians(160.0f), 1.0f, near, far);
    v.viewProj = v.proj * v.view;
    v.perspective = true;
    v.nearPlane = near;
    v.farPlane = far;
    // Radians per texel are largest at the disk's centre: the image there moves by 1/2 per radian.
    v.texelWorldSize = 4.0f * kParaboloidWindow / size;
    v.projection = LightView::Projection::Paraboloid;
    out.space.views.push_back(v);
    // The lookup reads hemisphere 0 in front of the plane through the light across its axis, 1
    // behind it: a hemisphere is needed when a visible receiver lies on its side.
    if (seen && size_t(h) < seen->size()) {  // point.fit_visible: the pixels' own images
      const ViewPixelBounds& b = (*seen)[size_t(h)];
      out.needed.push_back(b.valid);
      if (fit && b.valid) {
        LightView& fitted = out.space.views.back();
        fitted.paraboloidWindow = paraboloidWindowAround(b.lo, b.hi, size, snap, false);
        fitted.texelWorldSize /= std::min(fitted.paraboloidWindow.z, fitted.paraboloidWindow.w);
      }
      continue;
    }
    std::vector<glm::vec4> planes = frustum;
    planes.push_back(glm::vec4(axes[h], -glm::dot(axes[h], light.position)));
    const std::vector<glm::vec3> receivers = clipCornersToPlanes(box, planes);
    out.needed.push_back(!receivers.empty());
    if (fit && !receivers.empty()) {
      std::vector<glm::vec3> dirs;
      const glm::mat3 toView(v.view);
      for (const glm::vec3& p : receivers) {
        const glm::vec3 d = toView * (p - light.position);
        // A receiver at the light: it sees every direction, so the window is the whole disk.
        if (!(glm::length(d) > 1e-6f * far)) {
          dirs.clear();
          break;
        }
        dirs.push_back(glm::normalize(d));
      }
      out.space.views.back().paraboloidWindow = fitParaboloidWindow(dirs, size, snap);
      out.space.views.back().texelWorldSize /= out.space.views.back().paraboloidWindow.z;  // square
    }
  }
  return out;
}

std::unique_ptr<Layout> makeDualParaboloidLayout() {
  return makePointLayout(
      {.id = "dual-paraboloid",
       .help = "point light: two paraboloid views, one per hemisphere (Brabec, Annen & Seidel 2002); casters "
               "tessellated so their bent edges stay within paraboloid.max_error texels",
       .glslModule = "layouts/dual_paraboloid.glsl",
       .unit = "hemispheres",
       .params = {{.key = "paraboloid.max_error",
                   .type = ParamType::Float,
                   .min = 0.05,
                   .max = 16,
                   .defaultValue = 0.5,
                   .unit = "texels",
                   .help = "largest distance between a tessellated caster edge and its true (circle-arc) image in a "
                           "paraboloid map; smaller = more tessellation",
                   .logScale = true},
                  {.key = "paraboloid.fit",
                   .type = ParamType::Bool,
                   .defaultValue = 1,
                   .help = "fit each hemisphere's map to the directions of the receivers the camera sees in it (the "
                           "survey's focusing, beyond Brabec et al.): the part of the disk they fill is zoomed to the "
                           "whole map; off: the whole hemisphere"}},
       .views = [](const Light& light, const LayoutInput& in, const std::vector<ViewPixelBounds>* seen, AtlasHold*) {
         return paraboloidViews(light, in, seen);
       }});
}

}  // namespace sl
