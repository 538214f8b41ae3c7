// Ray-traced ground truth for the shadow term (Embree 3). It shades exactly the rasterized
// G-buffer the techniques shade, so only the visibility differs between technique and truth.
#pragma once

#include "scene/scene.h"

#include <string>
#include <vector>

namespace sl {

struct GBufferView {
  int width = 0;
  int height = 0;
  // width*height*4 floats each, row 0 = bottom (OpenGL readback order).
  // position.w = 1 where a surface was rasterized, 0 for background.
  const float* worldPosition = nullptr;
  const float* worldNormal = nullptr;  // normalized geometric normal facing the camera
};

struct ReferenceOptions {
  double time = 0.0;      // scene time, for moving instances
  int lightSamples = 64;  // used only when scene.light.radius > 0
  int threads = 0;        // 0 = hardware concurrency
};

// Visibility in [0,1] per pixel (1 = lit), 0 for background pixels; row order as the G-buffer.
// Alpha-masked materials are honoured through an Embree intersection filter.
class ReferenceTracer {
 public:
  explicit ReferenceTracer(const Scene& scene, double time = 0.0);
  ~ReferenceTracer();
  ReferenceTracer(const ReferenceTracer&) = delete;
  ReferenceTracer& operator=(const ReferenceTracer&) = delete;

  std::vector<float> visibility(const GBufferView& gbuffer, const ReferenceOptions& options) const;
  // One shadow ray; true when the segment from p toward the light is unoccluded.
  bool pointLit(const glm::vec3& p, const glm::vec3& n) const;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace sl
