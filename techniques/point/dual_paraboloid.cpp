#include "point/dual_paraboloid.h"

#include "part/light_frame.h"
#include "point/point_layout.h"

#include <glm/gtc/matrix_transform.hpp>

#include <string>

namespace sl {

FaceViews paraboloidViews(const Light& light, const LayoutInput& in) {
  const Bounds bounds = in.scene->boundsAt(in.time);
  const int size = in.params->i("shadowmap.size");
  const float far = pointLightFar(light, bounds);
  const float near = far * 1e-4f;  // as the cube's: linear depth, casters touching the light kept
  const std::vector<glm::vec3> box = boxCorners(bounds);
  const std::vector<glm::vec4> seen = frustumPlanes(in.cameraProj * in.cameraView);
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
    std::vector<glm::vec4> planes = seen;
    planes.push_back(glm::vec4(axes[h], -glm::dot(axes[h], light.position)));
    out.needed.push_back(!clipCornersToPlanes(box, planes).empty());
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
                   .logScale = true}},
       .views = paraboloidViews});
}

}  // namespace sl
