// Ray-traced ground truth for the shadow term (Embree 3). It shades exactly the rasterized
// G-buffer the techniques shade, so only the visibility differs between technique and truth.
#pragma once

#include "scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace sl {

struct GBufferView {
  int width = 0;
  int height = 0;
  // width*height*4 floats each, row 0 = bottom (OpenGL readback order).
  // position.w = 1 where a surface was rasterized, 0 for background.
  const float* worldPosition = nullptr;
  const float* worldNormal = nullptr;  // shading normal, turned to the side the camera sees
  // Optional (Renderer::gSurface): 4 uints per pixel, instance index + 1 (0 = unknown) and the
  // triangle index in that instance's mesh. With it the tracer starts each ray on the exact
  // plane of the rasterized triangle (see docs/reference.md, "Ray origin").
  const uint32_t* surface = nullptr;
};

struct ReferenceOptions {
  double time = 0.0;      // scene time, for moving instances
  int lightSamples = 64;  // used only when scene.light.radius > 0
  int threads = 0;        // 0 = hardware concurrency
  // Trace toward this light instead of the scene's (one of Scene::otherLights). Null: Scene::light.
  const Light* light = nullptr;
};

// Visibility in [0,1] per pixel (1 = lit), 0 for background pixels; row order as the G-buffer.
// Alpha-masked materials are honoured through an Embree intersection filter. Semi-transparent
// casters make it the light fraction reaching the pixel: blended surfaces (hair, glTF BLEND)
// multiply it by 1 - alpha, volumes by exp(-integral of sigma_t) (app/scene/volume_density.h).
class ReferenceTracer {
 public:
  explicit ReferenceTracer(const Scene& scene, double time = 0.0);
  ~ReferenceTracer();
  ReferenceTracer(const ReferenceTracer&) = delete;
  ReferenceTracer& operator=(const ReferenceTracer&) = delete;

  std::vector<float> visibility(const GBufferView& gbuffer, const ReferenceOptions& options) const;
  // One shadow ray; true when the segment from p toward the light is unoccluded. `instance` and
  // `triangle` (optional, -1 = unknown) name the surface p lies on, as the G-buffer does.
  bool pointLit(const glm::vec3& p, const glm::vec3& n, int instance = -1, int triangle = -1) const;
  // Light fraction reaching the point p in free space (no surface of its own: any hit beyond the
  // float tolerance of p counts), toward the light's centre; 0 outside a spot cone.
  float transmittanceToLight(const glm::vec3& p) const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace sl
