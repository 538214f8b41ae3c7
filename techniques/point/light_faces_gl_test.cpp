// The cube and tetrahedron layouts on the GPU, in the issue's numerically hard cases for a point
// light: the light inside a caster, on a receiver's plane, touching a caster, at the camera, a
// view toward a cube corner or a tetrahedron vertex, a range shorter than the distance to the nearest caster. Every
// case is finite, in [0, 1], and close to the ray-traced reference.
#include "point/light_faces.h"
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include <unistd.h>

namespace sl {
namespace {

const char* kPointScene = R"({"objects":[
  {"name":"ground","shape":"plane","size":[12,12],"subdivisions":12},
  {"name":"box","shape":"box","size":[1,1,1],"transform":{"translate":[0,0.5,0]}},
  {"name":"ball","shape":"sphere","radius":0.4,"transform":{"translate":[2,0.4,1]}},
  {"name":"post","shape":"cylinder","radius":0.1,"height":2,"transform":{"translate":[-2,1,-1]}}],
  "light":{"type":"point","position":[0.5,2.5,0.5]},
  "cameras":[{"position":[5,4,6],"target":[0,0.3,0],"fov_deg":60}]})";

struct PointCase {
  std::string name;
  std::function<void(Scene&, Camera&)> setup;
};

std::vector<PointCase> pointCases() {
  return {
      {"light inside a caster",
       [](Scene& s, Camera&) {
         s.light.position = {0.1f, 0.5f, -0.1f};
       }},
      {"light on the ground's plane",
       [](Scene& s, Camera&) {
         s.light.position = {3.0f, 0.0f, -2.0f};
       }},
      {"light touching the box's top",
       [](Scene& s, Camera&) {
         s.light.position = {0.2f, 1.0f, 0.1f};
       }},
      {"light at the camera", [](Scene& s, Camera& c) { s.light.position = c.position; }},
      {"view toward a cube corner",
       [](Scene& s, Camera& c) {
         s.light.position = {0.0f, 3.0f, 0.0f};
         c.position = s.light.position + glm::vec3(-0.5f, 0.5f, -0.5f);
         c.target = c.position + glm::vec3(1.0f, -1.0f, 1.0f);
       }},
      {"view toward a tetrahedron vertex (three faces meet)",
       [](Scene& s, Camera& c) {
         s.light.position = {0.0f, 3.0f, 0.0f};
         c.position = s.light.position + glm::vec3(0.0f, 0.3f, 0.0f);
         c.target = c.position - tetrahedronFaceSet().faces[1].axis;
       }},
      {"range shorter than the nearest caster",
       [](Scene& s, Camera&) {
         s.light.position = {0.0f, 3.5f, 0.0f};
         s.light.range = 1.5f;
       }},
  };
}

// Every hard case under each preset with `values`: finite, in [0, 1], at most 3 % wrong.
void expectHardPointCasesHold(const std::vector<const char*>& presets, const std::vector<std::string>& values) {
  test::GlHarness h;
  for (const PointCase& c : pointCases()) {
    Scene scene =
        loadScene(test::writeTempFile("cube_gl_" + std::to_string(::getpid()) + ".json", kPointScene), test::kAssets);
    c.setup(scene, scene.cameras.front());
    for (const char* preset : presets) {
      const test::Frame f = test::renderOnce(h, scene, preset, values, 96, 54);
      for (size_t i = 0; i < f.visibility.size(); i += 2) {
        ASSERT_TRUE(std::isfinite(f.visibility[i])) << c.name << " " << preset;
        ASSERT_GE(f.visibility[i], 0.0f) << c.name << " " << preset;
        ASSERT_LE(f.visibility[i], 1.0f) << c.name << " " << preset;
      }
      const double wrong = test::wrongPct(scene, f);
      EXPECT_LE(wrong, 3.0) << c.name << " " << preset;
    }
  }
}

TEST(LightFacesGl, HardPointLightCasesStayFiniteAndNearTheReference) {
  expectHardPointCasesHold(
      {"cube", "cube-pcf", "tetrahedron", "tetrahedron-pcf", "dual-paraboloid", "dual-paraboloid-pcf"},
      {"shadowmap.size=256"});
  // Liao's packing: one layer with the four faces' texels.
  expectHardPointCasesHold({"tetrahedron-packed", "tetrahedron-packed-pcf"}, {"shadowmap.size=512"});
  // The cube's faces in one atlas with the six 256² faces' texels.
  expectHardPointCasesHold({"cube-atlas"}, {"shadowmap.size=627"});
}

// The same with each view fitted to the pixels that read it (point.fit_visible): a light inside a
// caster or at the camera leaves views no pixel reads, and pixels at the light itself.
TEST(LightFacesGl, HardPointLightCasesHoldWithViewsFittedToThePixels) {
  expectHardPointCasesHold({"cube", "tetrahedron", "dual-paraboloid"}, {"shadowmap.size=256", "point.fit_visible=on"});
}

// Looking away from the lamp the cube draws 3 of its 6 faces and the tetrahedron 3 of 4 (each of its faces covers
// more), and the picture is still right.
TEST(LightFacesGl, UndrawnFacesCostNoDrawAndChangeNothingSeen) {
  test::GlHarness h;
  const Scene scene = loadScene("street", test::kAssets);
  h.renderer.setScene(scene);
  for (const auto& [preset, status] : {std::pair<std::string, std::string>{"cube", "cube: 3 of 6 faces drawn"},
                                       {"tetrahedron", "tetrahedron: 3 of 4 faces drawn"}}) {
    Viewport vp(makeTechnique(preset, {"shadowmap.size=256"}));
    FrameInput in;
    in.camera =
        *std::find_if(scene.cameras.begin(), scene.cameras.end(), [](const Camera& c) { return c.name == "away"; });
    in.width = 96;
    in.height = 54;
    h.renderer.render(in, {&vp});
    EXPECT_EQ(vp.layout->status().rfind(status + ";", 0), 0u) << vp.layout->status();  // then the windows
    const test::Frame f = test::readFrame(h.renderer, vp, 96, 54);
    EXPECT_LE(test::wrongPct(scene, f), 1.0) << preset;
  }
}

// A bar passing just under the lamp spans most of the lower hemisphere: the paraboloid bends its
// long edges into arcs, and only the tessellation keeps its shadow's outline. At 256² the coarse
// budget (16 texels: 2-3 pieces an edge) must be clearly worse than the default (0.5 texels).
TEST(DualParaboloidGl, TessellationKeepsBentEdgesOnTheirArcs) {
  test::GlHarness h;
  const Scene scene = loadScene(test::writeTempFile("paraboloid_bar_" + std::to_string(::getpid()) + ".json", R"({
    "objects":[{"name":"ground","shape":"plane","size":[30,30],"subdivisions":4},
      {"name":"bar","shape":"box","size":[20,0.1,0.1],"transform":{"translate":[0,2.5,0]}}],
    "light":{"type":"point","position":[0,3,0.3]},
    "cameras":[{"position":[0,14,9],"target":[0,0,0],"fov_deg":70}]})"),
                                test::kAssets);
  double wrong[2];
  const char* budgets[2] = {"paraboloid.max_error=0.5", "paraboloid.max_error=16"};
  for (int i = 0; i < 2; ++i) {
    const test::Frame f = test::renderOnce(h, scene, "dual-paraboloid", {"shadowmap.size=256", budgets[i]}, 160, 90);
    wrong[i] = test::wrongPct(scene, f);
  }
  EXPECT_LT(wrong[0], 1.0);
  EXPECT_LT(wrong[0] * 3.0, wrong[1]) << "default " << wrong[0] << " %, coarse " << wrong[1] << " %";
}

}  // namespace
}  // namespace sl
