// Where the deep map's texels go (deep_fit.h): the window holds the semi-transparent casters'
// light-space bounds, covers the whole map where it cannot fit, and the viewport that rasterizes
// it maps it onto the deep map exactly.
#include "deep/deep_fit.h"
#include "tests/assets_dir.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

namespace sl {
namespace {

// A sun straight down over a 40 x 40 window: the hair scene's ball fills a small part of it.
LightView sunOverHair() {
  LightView v;
  v.view = glm::lookAt(glm::vec3(0, 20, 0), glm::vec3(0), glm::vec3(0, 0, -1));
  v.proj = glm::ortho(-20.0f, 20.0f, -20.0f, 20.0f, 0.1f, 60.0f);
  v.viewProj = v.proj * v.view;
  return v;
}

glm::vec2 uvOf(const LightView& v, const glm::vec3& p) {
  const glm::vec4 c = v.viewProj * glm::vec4(p, 1.0f);
  return glm::vec2(c) / c.w * 0.5f + 0.5f;
}

TEST(DeepFit, WindowHoldsTheSemiTransparentCastersAndLittleElse) {
  const Scene scene = loadScene("hair", test::kAssets);
  const LightView view = sunOverHair();
  const DeepWindow w = deepFitWindow(scene, 0.0, view, 512, 32);
  Bounds hair;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == "fur") {
      const Bounds b = scene.instanceBoundsAt(i, 0.0);
      hair.add(b.min), hair.add(b.max);
    }
  ASSERT_FALSE(hair.empty()) << "the hair scene names its strands 'fur'";
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 p((c & 1) ? hair.max.x : hair.min.x, (c & 2) ? hair.max.y : hair.min.y,
                      (c & 4) ? hair.max.z : hair.min.z);
    const glm::vec2 d = w.toDeep(uvOf(view, p));
    EXPECT_GE(d.x, 0.0f);
    EXPECT_GE(d.y, 0.0f);
    EXPECT_LE(d.x, 1.0f);
    EXPECT_LE(d.y, 1.0f);
  }
  EXPECT_LT(w.size.x, 0.5f) << "the strands cover a small part of a 40-unit window";
  EXPECT_LT(w.size.y, 0.5f);
  EXPECT_NEAR(glm::length(w.toLayer(w.toDeep(glm::vec2(0.3f, 0.6f))) - glm::vec2(0.3f, 0.6f)), 0.0f, 1e-6f);
}

TEST(DeepFit, WholeMapWhereItCannotFit) {
  const LightView view = sunOverHair();
  const DeepWindow whole{};
  EXPECT_EQ(deepFitWindow(loadScene("basic", test::kAssets), 0.0, view, 512, 32), whole)
      << "no semi-transparent caster";
  LightView warped = view;
  warped.projection = LightView::Projection::LogWarp;
  EXPECT_EQ(deepFitWindow(loadScene("hair", test::kAssets), 0.0, warped, 512, 32), whole) << "the log warp bends";
  LightView behind = view;  // a perspective light inside the hair ball: corners behind it
  behind.view = glm::lookAt(glm::vec3(0, 1, 0), glm::vec3(0, 0, 0), glm::vec3(0, 0, -1));
  behind.proj = glm::perspective(1.0f, 1.0f, 0.1f, 50.0f);
  behind.viewProj = behind.proj * behind.view;
  behind.perspective = true;
  EXPECT_EQ(deepFitWindow(loadScene("hair", test::kAssets), 0.0, behind, 512, 32), whole);
}

TEST(DeepFit, ViewportMapsTheWindowOntoTheDeepTexels) {
  const Scene scene = loadScene("hair", test::kAssets);
  for (int size : {64, 512, 2048}) {
    for (int magnify : {1, 4, 32}) {
      const DeepWindow w = deepFitWindow(scene, 0.0, sunOverHair(), size, magnify);
      const glm::ivec4 vp = deepViewport(w, size);
      EXPECT_NEAR(w.size.x, float(size) / float(vp.z), 1e-6f) << size << " " << magnify;
      EXPECT_NEAR(w.size.y, float(size) / float(vp.w), 1e-6f);
      EXPECT_NEAR(w.origin.x, -float(vp.x) / float(vp.z), 1e-6f);
      EXPECT_NEAR(w.origin.y, -float(vp.y) / float(vp.w), 1e-6f);
      EXPECT_LE(vp.z, size * magnify) << "no more magnification than the viewport allows";
      EXPECT_GE(w.size.x, 1.0f / float(magnify) - 1e-6f);
    }
  }
}

}  // namespace
}  // namespace sl
