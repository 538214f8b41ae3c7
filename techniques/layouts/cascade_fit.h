// Geometry of cascaded / parallel-split shadow maps (Zhang et al. 2006, Engel 2007): where the
// camera's depth range is split, and the light window of one split, fitted to the split's
// bounding sphere and snapped to whole texels so that it does not shimmer.
#pragma once

#include "part/part.h"

#include <vector>

namespace sl {

enum class SplitScheme { Uniform = 0, Logarithmic = 1, Practical = 2 };

// count + 1 camera view depths from zNear to zFar: uniform C_i = n + (f - n) i/m, logarithmic
// C_i = n (f/n)^(i/m), practical lambda * logarithmic + (1 - lambda) * uniform (Zhang 2006).
std::vector<float> cascadeSplits(int count, SplitScheme scheme, float lambda, float zNear, float zFar);

// The camera's intrinsics as the layout needs them: near/far planes and the tangents of the
// half field of view, read back from a perspective projection matrix.
struct CameraFrustum {
  float zNear = 0.1f, zFar = 100.0f;
  float tanHalfX = 1.0f, tanHalfY = 1.0f;
  glm::vec3 eye{0.0f}, forward{0.0f, 0.0f, -1.0f};
};
CameraFrustum cameraFrustum(const glm::mat4& view, const glm::mat4& proj);

// The projection of the camera frustum between view depths a and b (same field of view).
glm::mat4 sliceProjection(const glm::mat4& proj, float a, float b);

// The smallest sphere around the frustum slice [a, b]: it depends only on a, b and the field
// of view, not on where the camera looks, so a window sized by it keeps its texel size while
// the camera turns (Engel 2007, "stable cascades").
struct Sphere {
  glm::vec3 center{0.0f};
  float radius = 0.0f;
};
Sphere sliceBoundingSphere(const CameraFrustum& cam, float a, float b);

// Orthographic light view around `sphere` ∩ the casters' light-space box (the scene): texel size
// from the smaller of the two on the fixed ladder (quantizeTexelSize), window origin on whole
// texels of the fixed light basis, depth from the casters toward the light to the sphere's far
// side. Without `snap` the window is centred with the exact texel size (what snapping is
// measured against).
LightView fitSphereOrthographic(const glm::mat4& lightView, const Sphere& sphere, const std::vector<glm::vec3>& casters,
                                int size, bool snap, const LayoutJitter& jitter);

}  // namespace sl
