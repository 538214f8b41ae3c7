// Scenes of several lights (render/other_lights.cpp): every shadowed light has maps of its own,
// each is measured against the reference traced toward that light, and the colour sums every
// light (an unshadowed one lights through casters). street-lamps: three lamps and a spot.
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"
#include "tests/scene_truth_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <unistd.h>

namespace sl {
namespace {

test::SceneTruth lampsTruth(test::GlHarness& h, int w, int hgt) { return test::sceneTruth(h, "street-lamps", w, hgt); }

// Each light's visibility against its own reference: a light read through another's maps (or
// every light given the first one's) is tens of percent wrong, since the lamps stand metres apart.
TEST(ManyLightsGl, EveryShadowedLightIsMeasuredAgainstItsOwnReference) {
  test::GlHarness h;
  const test::SceneTruth t = lampsTruth(h, 160, 90);
  ASSERT_EQ(t.scene.otherLights.size(), 3u);
  ASSERT_EQ(t.reference.otherLights.size(), 3u);
  for (const char* preset : {"cube", "tetrahedron"}) {
    Viewport vp(makeTechnique(preset, {"shadowmap.size=512"}));
    test::renderFromCut(h, t.in, vp);
    EXPECT_LE(viewportErrorMetrics(vp, t.reference).wrongPixelPct, 3.0) << preset << ", light 1";
    for (size_t k = 0; k < 3; ++k) {
      const Texture2D* tex = vp.otherLightVisibility(k);
      ASSERT_NE(tex, nullptr) << preset << ", light " << k + 2;
      const std::vector<float> v = visibilityChannel(*tex);
      const ErrorMetrics own =
          compareVisibility(v.data(), t.reference.otherLights[k].data(), t.reference.valid.data(), v.size());
      const ErrorMetrics first =
          compareVisibility(v.data(), t.reference.visibility.data(), t.reference.valid.data(), v.size());
      EXPECT_EQ(own.nonfinite, 0) << preset << ", light " << k + 2;
      EXPECT_LE(own.wrongPixelPct, 3.0) << preset << ", light " << k + 2;
      // The instrument: this light's truth is not the first light's.
      EXPECT_GE(first.wrongPixelPct, 10.0) << preset << ", light " << k + 2;
    }
    // The colour sums every light: against the same shading with the reference's visibilities.
    const double image =
        viewportImageError(h.renderer, t.in, vp, t.reference.visibility, t.reference.valid, t.reference.otherLights)
            .imageWrongPct;
    EXPECT_LE(image, 3.0) << preset;
    EXPECT_NE(vp.status().find("4 lights, 4 shadowed"), std::string::npos) << vp.status();
  }
  // Without the other lights' visibilities the shading of a scene of several lights is refused.
  Viewport vp(makeTechnique("standard"));
  test::renderFromCut(h, t.in, vp);
  EXPECT_THROW(h.renderer.shadeWithVisibility(t.in, t.reference.visibility), std::invalid_argument);
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// The colour is the lights' sum: the same frame shaded with every other light in full shadow
// differs wherever they reach, and the first light's share is unchanged by them.
TEST(ManyLightsGl, ColourChangesWithEachLightsVisibility) {
  test::GlHarness h;
  const test::SceneTruth t = lampsTruth(h, 160, 90);
  const auto& ref = t.reference;
  Viewport vp(makeTechnique("standard"));
  test::renderFromCut(h, t.in, vp);  // the frame shaded below (the reference may come from the cache)
  const std::vector<unsigned char> all = h.renderer.shadeWithVisibility(t.in, ref.visibility, ref.otherLights);
  std::vector<std::vector<float>> dark = ref.otherLights;
  for (auto& v : dark) std::fill(v.begin(), v.end(), 0.0f);
  const std::vector<unsigned char> firstOnly = h.renderer.shadeWithVisibility(t.in, ref.visibility, dark);
  ASSERT_EQ(all.size(), firstOnly.size());
  size_t brighter = 0, darker = 0, covered = 0;
  for (size_t i = 0; i < ref.valid.size(); ++i) {
    if (!ref.valid[i]) continue;
    ++covered;
    brighter += all[4 * i + 1] > firstOnly[4 * i + 1] + 2;
    darker += all[4 * i + 1] + 2 < firstOnly[4 * i + 1];
  }
  EXPECT_GT(brighter, covered / 5) << "the other lights reach a fifth of the view at least";
  EXPECT_EQ(darker, 0u) << "a light only adds";
}

// lights.shadowed: a shadow budget. Lights beyond it make no maps and light through casters, so
// the colour only brightens, and the status says how many were shadowed.
TEST(ManyLightsGl, ABudgetOfShadowedLightsLeavesTheRestUnshadowed) {
  test::GlHarness h;
  const test::SceneTruth t = lampsTruth(h, 160, 90);
  Viewport all(makeTechnique("cube", {"shadowmap.size=256"}));
  Viewport two(makeTechnique("cube", {"shadowmap.size=256", "lights.shadowed=2"}));
  test::renderFromCut(h, t.in, all);
  const std::vector<unsigned char> allColour = all.colorTexture()->readRgba8();
  test::renderFromCut(h, t.in, two);
  const std::vector<unsigned char> twoColour = two.colorTexture()->readRgba8();
  EXPECT_NE(two.otherLightVisibility(0), nullptr);
  EXPECT_EQ(two.otherLightVisibility(1), nullptr);
  EXPECT_EQ(two.otherLightVisibility(2), nullptr);
  EXPECT_NE(two.status().find("4 lights, 2 shadowed"), std::string::npos) << two.status();
  EXPECT_LT(two.shadowTexels(), all.shadowTexels());
  size_t brighter = 0;
  for (size_t i = 0; i < t.reference.valid.size(); ++i) {
    if (!t.reference.valid[i]) continue;
    EXPECT_GE(twoColour[4 * i + 1] + 2, allColour[4 * i + 1]) << "pixel " << i;
    brighter += twoColour[4 * i + 1] > allColour[4 * i + 1] + 8;
  }
  EXPECT_GT(brighter, 50u) << "the unshadowed lamps light what their shadows darkened";
}

// An unshadowed light ("shadow": false) lights through casters and makes no maps: the ground in
// the sun's shadow of a box is as bright as with no box there, while the same scene with the sun
// shadowed darkens it.
TEST(ManyLightsGl, AnUnshadowedLightLightsThroughCasters) {
  test::GlHarness h;
  auto sceneWithSun = [](bool shadowed, bool box) {
    const std::string objects =
        std::string(R"({"name":"ground","shape":"plane","size":[20,20],"color":[0.3,0.3,0.3]})") +
        (box ? R"(,{"name":"box","shape":"box","size":[1,1,1],"transform":{"translate":[0,0.5,0]}})" : "");
    const std::string json = R"({"objects":[)" + objects + R"(],"lights":[
        {"type":"point","position":[1,6,3],"range":30},
        {"type":"directional","direction":[1,-1,0],"shadow":)" +
                             (shadowed ? "true" : "false") + R"(}],
        "cameras":[{"name":"top","position":[1,8,0.01],"target":[1,0,0],"fov_deg":40}]})";
    return loadScene(test::writeTempFile("many_lights_sun_" + std::to_string(::getpid()) + ".json", json),
                     test::kAssets);
  };
  auto greenAt = [&](const Scene& scene, glm::vec3 world) {
    h.renderer.setScene(scene);
    FrameInput in;
    in.camera = scene.cameras.front();
    in.width = 96;
    in.height = 96;
    Viewport vp(makeTechnique("standard"));
    test::renderFromCut(h, in, vp);
    const glm::vec4 clip = cameraProjection(in.camera, 1.0f) * cameraView(in.camera) * glm::vec4(world, 1.0f);
    const int x = int((clip.x / clip.w * 0.5f + 0.5f) * in.width), y = int((clip.y / clip.w * 0.5f + 0.5f) * in.height);
    return int(vp.colorTexture()->readRgba8()[4 * (size_t(y) * in.width + x) + 1]);
  };
  // The sun travels along +x and down at 45 degrees: the unit box shadows the ground from x = 0.5
  // to 1.5; (1, 0, 0) is in that shadow and lit by the point light (6 m above, beside the box).
  const glm::vec3 inSunShadow(1.0f, 0.0f, 0.0f);
  const int through = greenAt(sceneWithSun(false, true), inSunShadow);
  const int noBox = greenAt(sceneWithSun(false, false), inSunShadow);
  const int shadowed = greenAt(sceneWithSun(true, true), inSunShadow);
  EXPECT_NEAR(through, noBox, 3);
  EXPECT_LT(shadowed + 20, through) << "the shadowed sun darkens the box's shadow";
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// Sixteen lights (the most a file may list) of every type, one inside a closed box, one exactly
// on the ground, one unshadowed, under the representations and accumulations with per-light
// state: every light's visibility is finite and in [0, 1] and the colour has no magenta.
TEST(ManyLightsGl, SixteenLightsOfEveryTypeStayFinite) {
  test::GlHarness h;
  std::string lights;
  for (int i = 0; i < 10; ++i)
    lights += R"({"type":"point","position":[)" + std::to_string(-9 + 2 * i) + R"(,2.5,)" + std::to_string(i % 3 - 1) +
              R"(],"range":9},)";
  lights += R"({"type":"point","position":[4,0.5,4],"range":9},)";  // inside the closed box
  lights += R"({"type":"point","position":[-4,0,4]},)";             // on the ground plane
  lights += R"({"type":"spot","position":[0,6,0],"direction":[0,-1,0.2],"fov_deg":70},)";
  lights += R"({"type":"spot","position":[3,4,-3],"direction":[-1,-1,1],"fov_deg":40,"radius":0.2},)";
  lights += R"({"type":"directional","direction":[0.3,-1,0.2]},)";
  lights += R"({"type":"directional","direction":[-0.5,-1,0],"shadow":false})";
  const Scene scene = loadScene(test::writeTempFile("sixteen_lights_" + std::to_string(::getpid()) + ".json", R"({
    "objects":[{"name":"ground","shape":"plane","size":[30,30]},
      {"name":"box","shape":"box","size":[2,2,2],"transform":{"translate":[4,1,4]}},
      {"name":"ball","shape":"sphere","radius":0.7,"transform":{"translate":[-2,1,-1]}}],
    "lights":[)" + lights + R"(],
    "cameras":[{"name":"top","position":[0,12,10],"target":[0,0,0],"fov_deg":70}]})"),
                                test::kAssets);
  ASSERT_EQ(scene.otherLights.size(), 15u);
  h.renderer.setScene(scene);
  FrameInput in;
  in.camera = scene.cameras.front();
  in.width = 64;
  in.height = 36;
  for (const char* preset : {"cube-pcf", "vsm", "pcss", "pixel-correct"}) {
    Viewport vp(makeTechnique(preset, {"technique.layout=cube", "shadowmap.size=128"}));
    test::renderFromCut(h, in, vp, 3);
    EXPECT_NE(vp.status().find("16 lights, 15 shadowed"), std::string::npos) << preset << ": " << vp.status();
    for (size_t k = 0; k < 15; ++k) {
      const Texture2D* tex = vp.otherLightVisibility(k);
      if (k == 14) {
        EXPECT_EQ(tex, nullptr) << "the unshadowed sun has no maps";
        continue;
      }
      ASSERT_NE(tex, nullptr) << preset << ", light " << k + 2;
      for (float v : visibilityChannel(*tex)) {
        ASSERT_TRUE(std::isfinite(v)) << preset << ", light " << k + 2;
        ASSERT_GE(v, 0.0f) << preset << ", light " << k + 2;
        ASSERT_LE(v, 1.0f) << preset << ", light " << k + 2;
      }
    }
    const std::vector<unsigned char> rgba = vp.colorTexture()->readRgba8();
    for (size_t i = 0; i < rgba.size(); i += 4)
      ASSERT_FALSE(rgba[i] == 255 && rgba[i + 1] == 0 && rgba[i + 2] == 255) << preset << ": magenta at " << i / 4;
  }
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
}

// A light's "color" scales its direct term per channel, for the first light (shaded with the
// technique's visibility) and for another (summed by passes/light_direct.frag) alike: a red lamp
// leaves green and blue at the ambient level, and a red plus a blue lamp light the ground purple.
TEST(ManyLightsGl, LightsShadeInTheirColour) {
  test::GlHarness h;
  auto centreColour = [&h](const std::string& lights) {
    const Scene scene = loadScene(test::writeTempFile("coloured_lights_" + std::to_string(::getpid()) + ".json", R"({
      "objects":[{"name":"ground","shape":"plane","size":[20,20],"color":[0.5,0.5,0.5]}],
      "lights":[)" + lights + R"(],
      "cameras":[{"name":"top","position":[0,8,0.01],"target":[0,0,0],"fov_deg":40}]})"),
                                  test::kAssets);
    h.renderer.setScene(scene);
    FrameInput in;
    in.camera = scene.cameras.front();
    in.width = 32;
    in.height = 32;
    Viewport vp(makeTechnique("standard"));
    test::renderFromCut(h, in, vp);
    const std::vector<unsigned char> rgba = vp.colorTexture()->readRgba8();
    const size_t centre = 4 * (16 * 32 + 16);
    return glm::ivec3(rgba[centre], rgba[centre + 1], rgba[centre + 2]);
  };
  const std::string red = R"({"type":"point","position":[0,4,0],"color":[1,0,0]})";
  const std::string white = R"({"type":"point","position":[0,4,0]})";
  const std::string blue = R"({"type":"point","position":[0,4,0],"color":[0,0,1]})";
  // Ambient alone: sqrt(0.5 * 0.18) = 0.30 (77 of 255); straight under a white lamp 1.0 * 0.82 more.
  const glm::ivec3 w = centreColour(white), r = centreColour(red), rb = centreColour(red + "," + blue);
  EXPECT_NEAR(w.g, 255.0 * std::sqrt(0.5 * (0.18 + 0.82)), 3) << "white lamp straight above";
  EXPECT_NEAR(r.r, w.r, 2);
  EXPECT_NEAR(r.g, 255.0 * std::sqrt(0.5 * 0.18), 2);
  EXPECT_NEAR(r.b, 255.0 * std::sqrt(0.5 * 0.18), 2);
  EXPECT_NEAR(rb.r, w.r, 2) << "red from the first light";
  EXPECT_NEAR(rb.b, w.b, 2) << "blue from the other, through the sum";
  EXPECT_NEAR(rb.g, r.g, 2);
}

}  // namespace
}  // namespace sl
