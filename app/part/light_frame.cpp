#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {

glm::mat4 lightViewMatrix(const Light& light, float roll) {
  glm::vec3 forward = glm::normalize(light.direction);
  glm::vec3 up = std::abs(forward.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  glm::vec3 eye = light.positional() ? light.position : glm::vec3(0.0f);
  glm::mat4 view = glm::lookAt(eye, eye + forward, up);
  if (roll != 0.0f) view = glm::rotate(glm::mat4(1.0f), roll, glm::vec3(0, 0, 1)) * view;
  return view;
}

Light sampledLight(const Light& light, glm::vec2 diskPoint) {
  if (!(light.radius > 0.0f) || diskPoint == glm::vec2(0.0f)) return light;
  const glm::vec3 d = glm::normalize(light.direction);
  const glm::vec3 t1 = glm::normalize(glm::cross(d, std::abs(d.y) > 0.99f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 t2 = glm::cross(d, t1);
  const glm::vec3 offset = light.radius * (diskPoint.x * t1 + diskPoint.y * t2);
  Light out = light;
  if (light.positional())
    out.position = light.position + offset;
  else
    out.direction = glm::normalize(d + offset);
  return out;
}

Light pointAsSpot(const Light& point, const std::vector<glm::vec3>& receivers) {
  Light spot = point;
  spot.type = Light::Type::Spot;
  glm::vec3 centre(0.0f);
  int n = 0;
  for (const glm::vec3& p : receivers)
    if (glm::length(p - point.position) > 1e-6f) centre += glm::normalize(p - point.position), ++n;
  spot.direction = n > 0 && glm::length(centre) > 1e-3f ? glm::normalize(centre) : glm::vec3(0, -1, 0);
  float cosHalf = 1.0f;
  for (const glm::vec3& p : receivers)
    if (glm::length(p - point.position) > 1e-6f)
      cosHalf = std::min(cosHalf, glm::dot(glm::normalize(p - point.position), spot.direction));
  const float half = glm::degrees(std::acos(std::clamp(cosHalf, -1.0f, 1.0f))) + 2.0f;
  spot.fovDeg = 2.0f * std::clamp(half, 1.0f, kPointAsSpotMaxHalfDeg);
  return spot;
}

Light layoutLight(const LayoutInput& in) {
  const Light light = sampledLight(in.shadowedLight(), in.jitter.lightSample);
  if (light.type != Light::Type::Point) return light;
  const Bounds bounds = in.scene->boundsAt(in.time);
  std::vector<glm::vec3> receivers = clipFrustumToBox(in.cameraView, in.cameraProj, bounds);
  if (receivers.empty()) receivers = boxCorners(bounds);
  return pointAsSpot(light, receivers);
}

std::vector<glm::vec3> frustumCorners(const glm::mat4& view, const glm::mat4& proj) {
  glm::mat4 inv = glm::inverse(proj * view);
  std::vector<glm::vec3> out;
  for (int z = -1; z <= 1; z += 2)
    for (int y = -1; y <= 1; y += 2)
      for (int x = -1; x <= 1; x += 2) {
        glm::vec4 p = inv * glm::vec4(x, y, z, 1.0f);
        out.emplace_back(glm::vec3(p) / p.w);
      }
  return out;
}

std::vector<glm::vec3> boxCorners(const Bounds& b) {
  std::vector<glm::vec3> out;
  for (int i = 0; i < 8; ++i)
    out.emplace_back(i & 1 ? b.max.x : b.min.x, i & 2 ? b.max.y : b.min.y, i & 4 ? b.max.z : b.min.z);
  return out;
}

using Polygon = std::vector<glm::vec3>;

// Sutherland-Hodgman against the half-space dot(n, p) + d >= 0; new points land in `cap`.
static Polygon clipPolygon(const Polygon& poly, const glm::vec3& n, float d, std::vector<glm::vec3>& cap) {
  Polygon out;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::vec3& a = poly[i];
    const glm::vec3& b = poly[(i + 1) % poly.size()];
    float da = glm::dot(n, a) + d, db = glm::dot(n, b) + d;
    if (da >= 0) out.push_back(a);
    if ((da >= 0) != (db >= 0)) {
      glm::vec3 p = a + (b - a) * (da / (da - db));
      out.push_back(p);
      cap.push_back(p);
    }
  }
  return out;
}

// Orders the cap points around their centroid so they form the convex cap polygon.
static Polygon orderCap(std::vector<glm::vec3> pts, const glm::vec3& n) {
  if (pts.size() < 3) return {};
  glm::vec3 c(0.0f);
  for (auto& p : pts) c += p;
  c /= static_cast<float>(pts.size());
  glm::vec3 u =
      glm::normalize(std::abs(n.x) < 0.9f ? glm::cross(n, glm::vec3(1, 0, 0)) : glm::cross(n, glm::vec3(0, 1, 0)));
  glm::vec3 v = glm::cross(n, u);
  std::sort(pts.begin(), pts.end(), [&](const glm::vec3& a, const glm::vec3& b) {
    return std::atan2(glm::dot(a - c, v), glm::dot(a - c, u)) < std::atan2(glm::dot(b - c, v), glm::dot(b - c, u));
  });
  return pts;
}

std::vector<glm::vec3> clipFrustumToBox(const glm::mat4& view, const glm::mat4& proj, const Bounds& box) {
  return clipCornersToBox(frustumCorners(view, proj), box);
}

std::vector<glm::vec4> boxPlanes(const Bounds& box) {
  return {{1, 0, 0, -box.min.x}, {-1, 0, 0, box.max.x}, {0, 1, 0, -box.min.y},
          {0, -1, 0, box.max.y}, {0, 0, 1, -box.min.z}, {0, 0, -1, box.max.z}};
}

std::vector<glm::vec4> frustumPlanes(const glm::mat4& viewProj) {
  const glm::mat4 m = glm::transpose(viewProj);  // rows of viewProj as columns
  std::vector<glm::vec4> planes;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {1.0f, -1.0f}) {
      glm::vec4 p = m[3] + sign * m[axis];  // w + x >= 0, w - x >= 0, ...
      const float n = glm::length(glm::vec3(p));
      planes.push_back(n > 0.0f ? p / n : p);
    }
  return planes;
}

std::vector<glm::vec3> clipCornersToBox(const std::vector<glm::vec3>& c, const Bounds& box) {
  return clipCornersToPlanes(c, boxPlanes(box));
}

std::vector<glm::vec3> clipCornersToPlanes(const std::vector<glm::vec3>& c, const std::vector<glm::vec4>& planes) {
  static const int faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  std::vector<Polygon> body;
  for (auto& f : faces) body.push_back({c[f[0]], c[f[1]], c[f[2]], c[f[3]]});
  for (const glm::vec4& plane : planes) {
    const glm::vec3 normal(plane);
    std::vector<Polygon> next;
    std::vector<glm::vec3> cap;
    for (auto& poly : body) {
      Polygon clipped = clipPolygon(poly, normal, plane.w, cap);
      if (clipped.size() >= 3) next.push_back(std::move(clipped));
    }
    Polygon capPoly = orderCap(cap, normal);
    if (!capPoly.empty()) next.push_back(std::move(capPoly));
    body = std::move(next);
    if (body.empty()) return {};
  }
  std::vector<glm::vec3> pts;
  for (auto& poly : body) pts.insert(pts.end(), poly.begin(), poly.end());
  return pts;
}

float quantizeTexelSize(float texel) {
  float steps = std::ceil(std::log2(texel) * 8.0f);
  return std::exp2(steps / 8.0f);
}

LightView fitOrthographic(const glm::mat4& lightView, const std::vector<glm::vec3>& receivers,
                          const std::vector<glm::vec3>& casters, int size, bool snap, const LayoutJitter& jitter) {
  glm::vec2 lo(1e30f), hi(-1e30f);
  float zNear = 1e30f, zFar = -1e30f;  // as positive distances along the light direction
  for (const auto& p : receivers) {
    glm::vec3 q = glm::vec3(lightView * glm::vec4(p, 1.0f));
    lo = glm::min(lo, glm::vec2(q));
    hi = glm::max(hi, glm::vec2(q));
    zNear = std::min(zNear, -q.z);
    zFar = std::max(zFar, -q.z);
  }
  for (const auto& p : casters) zNear = std::min(zNear, -(lightView * glm::vec4(p, 1.0f)).z);
  LightView ls;
  ls.perspective = false;
  glm::vec2 extent = glm::max(hi - lo, glm::vec2(1e-4f));
  // Keep texels square so that confidence and texel-grid views mean the same in x and y.
  float texel = std::max(extent.x, extent.y) / static_cast<float>(size);
  if (snap) {
    texel = quantizeTexelSize(texel * (1.0f + 2.0f / size));
    lo = glm::floor(lo / texel) * texel;
  } else {
    lo = (lo + hi) * 0.5f - glm::vec2(texel * size * 0.5f);
  }
  lo += jitter.offsetTexels * texel;
  ls.windowMin = lo;
  ls.windowMax = lo + glm::vec2(texel * size);
  float margin = std::max(1e-3f, (zFar - zNear) * 1e-3f);
  ls.nearPlane = zNear - margin;
  ls.farPlane = zFar + margin;
  ls.texelWorldSize = texel;
  ls.view = lightView;
  ls.proj = glm::ortho(ls.windowMin.x, ls.windowMax.x, ls.windowMin.y, ls.windowMax.y, ls.nearPlane, ls.farPlane);
  ls.viewProj = ls.proj * ls.view;
  return ls;
}

LightView fitPerspective(const Light& light, const glm::mat4& lightView, const std::vector<glm::vec3>& receivers,
                         const std::vector<glm::vec3>& casters, int size, bool crop, bool snap,
                         const LayoutJitter& jitter, bool squareTexels) {
  float zNear = 1e30f, zFar = 0.0f;
  for (const auto* set : {&receivers, &casters})
    for (const auto& p : *set) {
      float z = -(lightView * glm::vec4(p, 1.0f)).z;
      zFar = std::max(zFar, z);
      zNear = std::min(zNear, z);
    }
  float depthSpan = std::max(zFar, 1e-3f);
  zNear = std::max(zNear, depthSpan * 1e-3f);
  zFar = std::max(zFar * 1.001f, zNear * 1.01f);
  float halfTan = std::tan(glm::radians(light.fovDeg) * 0.5f);
  glm::mat4 proj = glm::perspective(glm::radians(light.fovDeg), 1.0f, zNear, zFar);
  glm::vec2 lo(-1.0f), hi(1.0f);
  if (crop) {
    glm::vec2 clo(1e30f), chi(-1e30f);
    for (const auto& p : receivers) {
      glm::vec4 c = proj * lightView * glm::vec4(p, 1.0f);
      if (c.w <= 1e-6f) {
        clo = glm::vec2(-1.0f);
        chi = glm::vec2(1.0f);
        break;
      }
      glm::vec2 ndc = glm::vec2(c) / c.w;
      clo = glm::min(clo, ndc);
      chi = glm::max(chi, ndc);
    }
    if (clo.x <= chi.x) {
      lo = glm::max(clo, glm::vec2(-1.0f));
      hi = glm::min(chi, glm::vec2(1.0f));
    }
  }
  glm::vec2 extent = glm::max(hi - lo, glm::vec2(1e-4f));
  if (squareTexels) extent = glm::vec2(std::max(extent.x, extent.y));
  glm::vec2 texel = extent / float(size);  // in NDC units
  if (snap) {
    texel = {quantizeTexelSize(texel.x), quantizeTexelSize(texel.y)};
    lo = glm::floor(lo / texel) * texel;
  } else {
    lo = (lo + hi) * 0.5f - texel * float(size) * 0.5f;
  }
  lo += jitter.offsetTexels * texel;
  const glm::vec2 span = texel * float(size);
  // Crop: map NDC [lo, lo+span] to [-1, 1].
  glm::mat4 cropM(1.0f);
  cropM[0][0] = 2.0f / span.x;
  cropM[1][1] = 2.0f / span.y;
  cropM[3][0] = -1.0f - 2.0f * lo.x / span.x;
  cropM[3][1] = -1.0f - 2.0f * lo.y / span.y;
  LightView ls;
  ls.perspective = true;
  ls.nearPlane = zNear;
  ls.farPlane = zFar;
  ls.windowMin = lo;
  ls.windowMax = lo + span;
  ls.texelWorldSize = halfTan * std::max(texel.x, texel.y);  // world size per texel at unit distance
  ls.view = lightView;
  ls.proj = cropM * proj;
  ls.viewProj = ls.proj * ls.view;
  return ls;
}

FocusBody focusBody(const LayoutInput& in) {
  FocusBody b;
  b.bounds = in.scene->boundsAt(in.time);
  b.size = in.params->i("shadowmap.size");
  b.casters = boxCorners(b.bounds);
  b.receivers = clipFrustumToBox(in.cameraView, in.cameraProj, b.bounds);
  if (b.receivers.empty()) b.receivers = b.casters;  // looking away from the scene: nothing to focus on
  b.lightView = lightViewMatrix(layoutLight(in), in.jitter.rotationRad);
  return b;
}

LightSpace focusedMap(const LayoutInput& in, const FocusBody& b) {
  const Light light = layoutLight(in);
  if (light.type == Light::Type::Spot)
    return LightSpace::single(
        fitPerspective(light, b.lightView, b.receivers, b.casters, b.size, true, false, in.jitter), b.size);
  return LightSpace::single(fitOrthographic(b.lightView, b.receivers, b.casters, b.size, false, in.jitter), b.size);
}

bool mapPointOf(const glm::vec3& world, const LightView& view, glm::vec3& uvLayer, float& depth) {
  const glm::vec4 clip = lightViewClip(view, world);  // the log warp (LogPSM) included
  if (!(clip.w > 1e-6f)) return false;
  uvLayer = glm::vec3(glm::vec2(clip) / clip.w * 0.5f + 0.5f, 0.0f);
  depth = (-(view.view * glm::vec4(world, 1.0f)).z - view.nearPlane) / (view.farPlane - view.nearPlane);
  return true;
}

glm::vec3 lightRayPoint(const LightView& view, glm::vec2 uv, float d) {
  const glm::mat4 invView = glm::inverse(view.view);
  glm::vec4 q = glm::inverse(view.proj) * glm::vec4(uv * 2.0f - 1.0f, 0.0f, 1.0f);
  q /= q.w;
  const float dist = view.nearPlane + d * (view.farPlane - view.nearPlane);
  const glm::vec3 p = view.perspective ? glm::vec3(q) * (dist / std::max(-q.z, 1e-12f)) : glm::vec3(q.x, q.y, -dist);
  return glm::vec3(invView * glm::vec4(p, 1.0f));
}

namespace {

// Andrew's monotone chain, for float and double points.
template <typename V>
std::vector<V> monotoneChainHull(std::vector<V> points) {
  std::sort(points.begin(), points.end(),
            [](const V& a, const V& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  auto cross = [](const V& o, const V& a, const V& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); };
  std::vector<V> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

}  // namespace

std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points) { return monotoneChainHull(std::move(points)); }
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points) { return monotoneChainHull(std::move(points)); }

std::vector<glm::dvec2> screenPoints(const std::vector<glm::vec3>& body, const glm::mat4& viewProj) {
  std::vector<glm::dvec2> ndc;
  for (const glm::vec3& p : body) {
    const glm::vec4 c = viewProj * glm::vec4(p, 1.0f);
    if (!(c.w > 0.0f)) continue;
    ndc.push_back(glm::clamp(glm::dvec2(c.x / c.w, c.y / c.w), glm::dvec2(-1.0), glm::dvec2(1.0)));
  }
  return ndc;
}

double screenShare(const std::vector<glm::dvec2>& ndc) {
  const std::vector<glm::dvec2> hull = convexHull(ndc);
  double area = 0.0;  // shoelace
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::dvec2& a = hull[i];
    const glm::dvec2& b = hull[(i + 1) % hull.size()];
    area += a.x * b.y - b.x * a.y;
  }
  return hull.size() < 3 ? 0.0 : std::abs(area) * 0.5 / 4.0;  // the screen is 2 x 2 in NDC
}

std::vector<glm::vec2> receiverHullInMap(const LightView& view, const std::vector<glm::vec3>& receivers) {
  if (view.projection != LightView::Projection::Matrix || receivers.empty()) return {};
  // A perspective view (or a warp's) sees the body's part in front of the light (w > 0; behind
  // it nothing reads the map): the body's points there and, between each point in front and
  // each behind, where the segment crosses w = wMin (the hull of those holds the clipped body).
  const float wMin = 1e-6f * std::max(view.farPlane, 1e-3f);
  std::vector<glm::vec4> clip;
  for (const glm::vec3& p : receivers) clip.push_back(view.viewProj * glm::vec4(p, 1.0f));
  std::vector<glm::vec4> front;
  for (const glm::vec4& a : clip) {
    if (a.w >= wMin) {
      front.push_back(a);
      continue;
    }
    for (const glm::vec4& b : clip)
      if (b.w >= wMin) front.push_back(glm::mix(a, b, (wMin - a.w) / (b.w - a.w)));
  }
  std::vector<glm::vec2> uv;
  for (const glm::vec4& c : front) {
    const glm::vec2 q = glm::vec2(c) / c.w * 0.5f + 0.5f;
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) return {};
    uv.push_back(q);
  }
  if (uv.empty()) return {};
  return convexHull(uv);
}

}  // namespace sl
