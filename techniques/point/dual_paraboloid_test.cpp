// The dual-paraboloid layout's mapping against values computed by hand, and the hemispheres a
// view needs.
#include "part/light_frame.h"
#include "point/dual_paraboloid.h"
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace sl {
namespace {

LayoutInput paraboloidInput(const Scene& scene, const Camera& cam, const ParamSet& params) {
  LayoutInput in;
  in.scene = &scene;
  in.cameraView = cameraView(cam);
  in.cameraProj = cameraProjection(cam, 16.0f / 9.0f);
  in.params = &params;
  return in;
}

// A direction theta off the hemisphere's axis lands at radius tan(theta / 2) of the unit disk
// (the stereographic image), scaled by 1 / kParaboloidWindow; depth is the distance from the
// light over [near, far]. Checked at 0, 30, 60, 90 degrees and 20 degrees past the rim, in four
// azimuths, for both hemispheres.
TEST(DualParaboloid, MapsDirectionsToTheStereographicDisk) {
  const Scene scene = loadScene("street", test::kAssets);
  const ParamSet params = makeTechnique("dual-paraboloid", {}).params;
  const FaceViews v = paraboloidViews(scene.light, paraboloidInput(scene, scene.cameras.front(), params));
  ASSERT_EQ(v.space.views.size(), 2u);
  const glm::vec3 axes[2] = {{0, -1, 0}, {0, 1, 0}};
  for (int h = 0; h < 2; ++h) {
    const LightView& view = v.space.views[h];
    for (float thetaDeg : {0.0f, 30.0f, 60.0f, 90.0f, 110.0f})
      for (float azimuthDeg : {0.0f, 90.0f, 200.0f, 300.0f}) {
        const float theta = glm::radians(thetaDeg), az = glm::radians(azimuthDeg);
        // A direction theta off the axis: rotate the axis toward x/z by theta about azimuth.
        const glm::vec3 side(std::cos(az), 0.0f, std::sin(az));
        const glm::vec3 d = std::cos(theta) * axes[h] + std::sin(theta) * side;
        const float dist = 3.0f;
        const glm::vec4 c = lightViewClip(view, scene.light.position + d * dist);
        ASSERT_EQ(c.w, 1.0f);
        EXPECT_NEAR(glm::length(glm::vec2(c)), std::tan(theta / 2.0f) / kParaboloidWindow, 1e-4f)
            << "hemisphere " << h << " theta " << thetaDeg << " azimuth " << azimuthDeg;
        const float depth = (c.z + 1.0f) * 0.5f;
        EXPECT_NEAR(depth, (dist - view.nearPlane) / (view.farPlane - view.nearPlane), 1e-5f);
      }
    EXPECT_EQ(lightViewClip(view, scene.light.position).w, 0.0f) << "the light itself is not in the map";
  }
}

// Looking down from under the lamp needs the lower hemisphere only; the default camera, above
// the lamp's level as well, needs both.
TEST(DualParaboloid, DrawsOnlyTheHemispheresAViewNeeds) {
  const Scene scene = loadScene("street", test::kAssets);
  const ParamSet params = makeTechnique("dual-paraboloid", {}).params;
  for (const Camera& cam : scene.cameras) {
    const FaceViews v = paraboloidViews(scene.light, paraboloidInput(scene, cam, params));
    EXPECT_TRUE(v.needed[0]) << cam.name << ": every camera sees the street below the lamp";
    // A visible point above the lamp's level needs the upper hemisphere; the check below is the
    // converse, with points sampled from the frustum.
    if (!v.needed[1]) {
      const glm::mat4 inv = glm::inverse(cameraProjection(cam, 16.0f / 9.0f) * cameraView(cam));
      const Bounds b = scene.boundsAt(0.0);
      for (int i = 0; i < 2000; ++i) {
        const glm::vec3 ndc(std::fmod(i * 0.618034f, 1.0f) * 2 - 1, std::fmod(i * 0.754878f, 1.0f) * 2 - 1,
                            std::fmod(i * 0.569840f, 1.0f) * 2 - 1);
        const glm::vec4 w = inv * glm::vec4(ndc, 1.0f);
        const glm::vec3 p = glm::vec3(w) / w.w;
        if (glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max)))
          ASSERT_LT(p.y, scene.light.position.y) << cam.name << ": a visible point above the lamp, upper undrawn";
      }
    }
  }
}

}  // namespace
}  // namespace sl
