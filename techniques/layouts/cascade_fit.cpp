#include "layouts/cascade_fit.h"

#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {

std::vector<float> cascadeSplits(int count, SplitScheme scheme, float lambda, float zNear, float zFar) {
  count = std::clamp(count, 1, kMaxLightViews);
  zNear = std::max(zNear, 1e-4f);
  zFar = std::max(zFar, zNear * 1.0001f);
  std::vector<float> out(static_cast<size_t>(count) + 1);
  for (int i = 0; i <= count; ++i) {
    const float t = static_cast<float>(i) / static_cast<float>(count);
    const float uniform = zNear + (zFar - zNear) * t;
    const float logarithmic = zNear * std::pow(zFar / zNear, t);
    float c = uniform;
    if (scheme == SplitScheme::Logarithmic) c = logarithmic;
    if (scheme == SplitScheme::Practical) c = lambda * logarithmic + (1.0f - lambda) * uniform;
    out[static_cast<size_t>(i)] = c;
  }
  // Exact end points: the first and last split must not lose pixels to rounding.
  out.front() = zNear;
  out.back() = zFar;
  return out;
}

CameraFrustum cameraFrustum(const glm::mat4& view, const glm::mat4& proj) {
  CameraFrustum c;
  // glm::perspective: proj[2][2] = -(f + n) / (f - n), proj[3][2] = -2 f n / (f - n).
  c.zNear = proj[3][2] / (proj[2][2] - 1.0f);
  c.zFar = proj[3][2] / (proj[2][2] + 1.0f);
  c.tanHalfX = 1.0f / proj[0][0];
  c.tanHalfY = 1.0f / proj[1][1];
  const glm::mat4 inv = glm::inverse(view);
  c.eye = glm::vec3(inv[3]);
  c.forward = -glm::normalize(glm::vec3(inv[2]));
  return c;
}

glm::mat4 sliceProjection(const glm::mat4& proj, float a, float b) {
  glm::mat4 p = proj;
  p[2][2] = -(b + a) / (b - a);
  p[3][2] = -2.0f * b * a / (b - a);
  return p;
}

Sphere sliceBoundingSphere(const CameraFrustum& cam, float a, float b) {
  // The slice's corners at depth z lie k z off the axis (k^2 = tan_x^2 + tan_y^2); the centre c
  // on the axis equidistant from the near and far corners: (c-a)^2 + (ka)^2 = (b-c)^2 + (kb)^2.
  const float k2 = cam.tanHalfX * cam.tanHalfX + cam.tanHalfY * cam.tanHalfY;
  const float c = std::min(0.5f * (a + b) * (1.0f + k2), b);
  const float radius = std::max(std::sqrt((c - a) * (c - a) + a * a * k2), std::sqrt((b - c) * (b - c) + b * b * k2));
  return Sphere{cam.eye + cam.forward * c, radius};
}

LightView fitSphereOrthographic(const glm::mat4& lightView, const Sphere& sphere, const std::vector<glm::vec3>& casters,
                                int size, bool snap, const LayoutJitter& jitter) {
  const glm::vec3 c = glm::vec3(lightView * glm::vec4(sphere.center, 1.0f));
  glm::vec2 sceneLo(1e30f), sceneHi(-1e30f);
  float sceneNear = 1e30f, sceneFar = -1e30f;
  for (const auto& p : casters) {
    const glm::vec3 q = glm::vec3(lightView * glm::vec4(p, 1.0f));
    sceneLo = glm::min(sceneLo, glm::vec2(q));
    sceneHi = glm::max(sceneHi, glm::vec2(q));
    sceneNear = std::min(sceneNear, -q.z);
    sceneFar = std::max(sceneFar, -q.z);
  }
  // Beyond Engel 2007: nothing outside the scene receives, so the window needs to cover only
  // sphere ∩ scene. The scene's light-space box does not move with the camera either, so the
  // texel size still changes only when the split's sphere does.
  const glm::vec2 sceneExtent = sceneHi - sceneLo;
  const float diameter = std::max(std::min(2.0f * sphere.radius, std::max(sceneExtent.x, sceneExtent.y)), 1e-4f);
  const glm::vec2 coverLo = glm::max(glm::vec2(c) - glm::vec2(sphere.radius), sceneLo);
  const glm::vec2 coverHi = glm::min(glm::vec2(c) + glm::vec2(sphere.radius), sceneHi);
  float texel = diameter / size;
  glm::vec2 lo = 0.5f * (coverLo + coverHi) - glm::vec2(0.5f * diameter);
  if (snap) {
    // Two texels of slack: the window origin moves down to whole texels, the cover stays inside.
    texel = quantizeTexelSize(diameter * (1.0f + 2.0f / size) / size);
    lo = glm::floor(coverLo / texel) * texel;
  }
  lo += jitter.offsetTexels * texel;
  // Casters toward the light come from the whole scene; beyond the scene nothing receives.
  const float zNear = std::min(-c.z - sphere.radius, sceneNear);
  const float zFar = std::max(std::min(-c.z + sphere.radius, sceneFar), zNear + 1e-3f);
  const float margin = std::max(1e-3f, (zFar - zNear) * 1e-3f);
  LightView v;
  v.perspective = false;
  v.view = lightView;
  v.windowMin = lo;
  v.windowMax = lo + glm::vec2(texel * size);
  v.nearPlane = zNear - margin;
  v.farPlane = zFar + margin;
  v.texelWorldSize = texel;
  v.proj = glm::ortho(v.windowMin.x, v.windowMax.x, v.windowMin.y, v.windowMax.y, v.nearPlane, v.farPlane);
  v.viewProj = v.proj * v.view;
  return v;
}

}  // namespace sl
