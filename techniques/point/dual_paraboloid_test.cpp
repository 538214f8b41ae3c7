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
  const ParamSet params = makeTechnique("dual-paraboloid", {"paraboloid.fit=off"}).params;
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

// Directions within `spread` radians of `axis`, from a fixed sequence.
std::vector<glm::vec3> directionsAround(const glm::vec3& axis, float spread, int count, int seed) {
  const glm::vec3 t1 =
      glm::normalize(glm::cross(axis, std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0)));
  const glm::vec3 t2 = glm::cross(axis, t1);
  std::vector<glm::vec3> out;
  for (int i = 0; i < count; ++i) {
    const float a = 6.2831853f * std::fmod((seed + i) * 0.618034f, 1.0f);
    const float r = spread * std::sqrt(std::fmod((seed + i) * 0.754878f, 1.0f));
    out.push_back(glm::normalize(std::cos(r) * axis + std::sin(r) * (std::cos(a) * t1 + std::sin(a) * t2)));
  }
  return out;
}

// The fitted window holds every direction between its inputs (normalized mixes of them, which lie
// on the sphere between them) at least 3 texels inside the map, zooms in, and with snapping keeps
// its zoom on the quarter-octave ladder and its centre on whole texels.
TEST(DualParaboloid, FittedWindowHoldsEveryDirectionBetweenItsInputs) {
  const int size = 512;
  for (int seed = 0; seed < 40; ++seed) {
    const float tilt = glm::radians(2.0f * seed), azimuth = 0.7f * seed;  // up to 78 degrees off the axis
    const glm::vec3 axis(std::sin(tilt) * std::cos(azimuth), std::sin(tilt) * std::sin(azimuth), -std::cos(tilt));
    const float spread = glm::radians(4.0f + 0.4f * seed);
    const std::vector<glm::vec3> dirs = directionsAround(axis, spread, 3 + seed % 6, seed);
    for (bool snap : {false, true}) {
      const glm::vec4 w = fitParaboloidWindow(dirs, size, snap);
      EXPECT_EQ(w.z, w.w);  // square
      ASSERT_GT(w.z, 1.0f) << "seed " << seed << ": directions within " << glm::degrees(spread) << " degrees";
      LightView view;
      view.projection = LightView::Projection::Paraboloid;
      view.paraboloidWindow = w;
      const float inside = 1.0f - 3.0f * 2.0f / size;
      // The inputs, the arcs between pairs of them (the border of what lies between) and mixes
      // of all of them (the inside).
      std::vector<glm::vec3> between;
      for (size_t i = 0; i < dirs.size(); ++i)
        for (size_t j = i; j < dirs.size(); ++j)
          for (int k = 0; k <= 16; ++k) between.push_back(glm::mix(dirs[i], dirs[j], k / 16.0f));
      for (int k = 0; k < 300; ++k) {
        glm::vec3 d(0.0f);
        for (size_t i = 0; i < dirs.size(); ++i) d += std::fmod((k + 1) * (i + 2) * 0.5698403f, 1.0f) * dirs[i];
        between.push_back(d);
      }
      float largest = 0.0f;
      for (const glm::vec3& d : between) {
        const glm::vec4 c = lightViewClip(view, glm::normalize(d));
        largest = std::max({largest, std::abs(c.x), std::abs(c.y)});
      }
      EXPECT_LE(largest, inside) << "seed " << seed;
      // Fitted, not merely inside: what lies between reaches most of the way to the border
      // (the margins leave 1 / 1.1 less 4 texels; the snapped zoom steps down by up to 2^(1/4)),
      // unless the zoom stopped at its largest.
      if (w.z < 64.0f) EXPECT_GT(largest, snap ? 0.72f : 0.85f) << "seed " << seed;
      if (snap) {
        const float quarterOctaves = std::log2(w.z) * 4.0f;
        EXPECT_NEAR(quarterOctaves, std::round(quarterOctaves), 1e-3f) << "seed " << seed;
        const float texel = 2.0f / (w.z * size);
        EXPECT_NEAR(w.x / texel, std::round(w.x / texel), 1e-2f) << "seed " << seed;
        EXPECT_NEAR(w.y / texel, std::round(w.y / texel), 1e-2f) << "seed " << seed;
      }
    }
  }
}

// No directions, directions all around (the light inside what is seen), or two opposite ones:
// the whole disk.
TEST(DualParaboloid, AWindowThatCannotBeBoundedIsTheWholeDisk) {
  const glm::vec4 whole(0.0f, 0.0f, 1.0f, 1.0f);
  EXPECT_EQ(fitParaboloidWindow({}, 512, true), whole);
  EXPECT_EQ(fitParaboloidWindow({{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}, 512, true),
            whole);
  EXPECT_EQ(fitParaboloidWindow({{1, 0, 0}, {-1, 0, 0}, {0, 0, -1}}, 512, false), whole);
  // The whole lower hemisphere's rim and pole: the window is the whole disk (no zoom).
  EXPECT_EQ(fitParaboloidWindow({{1, 0, 0}, {0, 1, 0}, {-0.7071f, -0.7071f, 0}, {0, 0, -1}}, 512, false).z, 1.0f);
}

// Every camera of street, fitted: points sampled in its frustum, the scene's bounds and the
// lamp's reach fall inside the window of the hemisphere that serves them, 3 texels from its
// border; the south-bench close-up, which looks away from the lamp, is zoomed in.
TEST(DualParaboloid, FittedWindowsHoldWhatEachCameraSees) {
  const Scene scene = loadScene("street", test::kAssets);
  const ParamSet params = makeTechnique("dual-paraboloid", {"shadowmap.size=512"}).params;
  const Bounds b = scene.boundsAt(0.0);
  for (const Camera& cam : scene.cameras) {
    const FaceViews v = paraboloidViews(scene.light, paraboloidInput(scene, cam, params));
    if (cam.name == "south-bench") EXPECT_GT(v.space.views[0].paraboloidWindow.z, 1.1f) << cam.name;
    const glm::mat4 inv = glm::inverse(cameraProjection(cam, 16.0f / 9.0f) * cameraView(cam));
    const float inside = 1.0f - 3.0f * 2.0f / v.space.size;
    for (int i = 0; i < 4000; ++i) {
      const glm::vec3 ndc(std::fmod(i * 0.618034f, 1.0f) * 2 - 1, std::fmod(i * 0.754878f, 1.0f) * 2 - 1,
                          std::fmod(i * 0.569840f, 1.0f) * 2 - 1);
      const glm::vec4 w = inv * glm::vec4(ndc, 1.0f);
      const glm::vec3 p = glm::vec3(w) / w.w;
      const glm::vec3 d = p - scene.light.position;
      const float far = v.space.views[0].farPlane;
      if (glm::any(glm::lessThan(p, b.min)) || glm::any(glm::greaterThan(p, b.max)) ||
          std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) > far)
        continue;
      const int h = -(v.space.views[0].view * glm::vec4(p, 1.0f)).z >= 0.0f ? 0 : 1;
      ASSERT_TRUE(v.needed[h]) << cam.name;
      const glm::vec4 c = lightViewClip(v.space.views[h], p);
      ASSERT_LE(std::max(std::abs(c.x), std::abs(c.y)), inside) << cam.name << " hemisphere " << h << " point " << i;
    }
  }
}

// point.fit_visible's windows fit each axis on its own: a box wide along x and flat along y
// keeps the whole disk along x (no magnification there) and zooms along y, the box inside with
// its margin; square, both axes take the wide side's zoom (here none: the whole disk).
TEST(DualParaboloid, AWindowFittedPerAxisZoomsOnlyWhereTheBoxIsNarrow) {
  const glm::vec2 lo(-0.9f, -0.1f), hi(0.9f, 0.2f);
  const int size = 512;
  const glm::vec4 w = paraboloidWindowAround(lo, hi, size, false, false);
  EXPECT_EQ(w.x, 0.0f);
  EXPECT_EQ(w.z, 1.0f);
  // 2 (1 - 8 / 512) / (1.1 * 0.3): the 5 % and the 4 texels on each side.
  EXPECT_NEAR(w.w, 2.0f * (1.0f - 8.0f / 512.0f) / 0.33f, 1e-3f);
  for (const glm::vec2 c : {lo, hi}) {
    const float y = (c.y - w.y) * w.w;
    EXPECT_LT(std::abs(y), 1.0f - 4.0f * 2.0f / size) << c.y;
  }
  EXPECT_EQ(paraboloidWindowAround(lo, hi, size, false, true), glm::vec4(0.0f, 0.0f, 1.0f, 1.0f));
}

}  // namespace
}  // namespace sl
