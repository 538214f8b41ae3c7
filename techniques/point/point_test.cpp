// Point lights without a GPU: the scene format, the reference against shadows computed by hand,
// and the cube layout's faces (every visible receiver inside its face's fitted window; faces the
// view does not need are not drawn).
#include "part/light_frame.h"
#include "point/cube_layout.h"
#include "reference/reference.h"
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

#include <unistd.h>

namespace sl {
namespace {

// Ground points facing up, one pixel each, for ReferenceTracer::visibility.
struct GroundRow {
  std::vector<float> position, normal;
  explicit GroundRow(const std::vector<glm::vec3>& points) {
    for (const glm::vec3& p : points) {
      position.insert(position.end(), {p.x, p.y, p.z, 1.0f});
      normal.insert(normal.end(), {0.0f, 1.0f, 0.0f, 0.0f});
    }
  }
  GBufferView view() const {
    GBufferView v;
    v.width = static_cast<int>(position.size() / 4);
    v.height = 1;
    v.worldPosition = position.data();
    v.worldNormal = normal.data();
    return v;
  }
};

// A ground plane and a ball of radius 0.5 at height 1, a point light `above` over its centre.
Scene ballUnderPoint(float above, const std::string& extra = "") {
  const std::string json =
      R"({"objects":[{"name":"ground","shape":"plane","size":[40,40]},)"
      R"({"name":"ball","shape":"sphere","radius":0.5,"segments":96,"transform":{"translate":[0,1,0]}}],)"
      R"("light":{"type":"point","position":[0,)" +
      std::to_string(above) + ",0]" + extra + "}}";
  return loadScene(test::writeTempFile("point_ball_" + std::to_string(::getpid()) + ".json", json), test::kAssets);
}

TEST(PointLight, SceneFormatReadsAPointLightAndAListOfOne) {
  const Scene s = ballUnderPoint(3.0f, R"(,"range":7.5,"radius":0.1)");
  EXPECT_EQ(s.light.type, Light::Type::Point);
  EXPECT_TRUE(s.light.positional());
  EXPECT_FLOAT_EQ(s.light.range, 7.5f);
  EXPECT_FLOAT_EQ(s.light.radius, 0.1f);
  EXPECT_EQ(s.light.position, glm::vec3(0, 3, 0));
  const Scene listed = loadScene(test::writeTempFile("point_list.json", R"({"objects":[{"shape":"box"}],
      "lights":[{"type":"point","position":[1,2,3]}]})"),
                                 test::kAssets);
  EXPECT_EQ(listed.light.type, Light::Type::Point);
  EXPECT_EQ(listed.light.position, glm::vec3(1, 2, 3));
}

TEST(PointLight, BadLightsNameTheFileAndTheField) {
  struct Case {
    std::string json, field, words;
  };
  const std::vector<Case> cases = {
      {R"("light":{"type":"point","position":[0,2,0],"radius":-1})", "light.radius", ">= 0"},
      {R"("light":{"type":"point","position":[0,2,0],"range":-3})", "light.range", "range > 0"},
      {R"("light":{"type":"point","position":[0,2,0],"range":0})", "light.range", "range > 0"},
      {R"("light":{"type":"point","position":[0,1e300,0]})", "light.position", "finite"},
      {R"("light":{"type":"point"})", "light.position", "needs a position"},
      {R"("light":{"type":"spot","range":3})", "light.range", "only a point light"},
      {R"("lights":{"type":"point","position":[0,2,0]})", "lights", "an array"},
      {R"("lights":[])", "lights", "empty"},
      {R"("lights":[3])", "lights[0]", "a light object"},
      {R"("lights":[{"type":"point","position":[0,2,0],"range":-1}])", "lights[0].range", "range > 0"},
      {R"("light":{"type":"point","position":[0,2,0]},"lights":[{"type":"point","position":[0,2,0]}])", "lights",
       "not both"},
      {R"("lights":[{"type":"point","position":[0,2,0]},{"type":"directional","direction":[0,-1,0]}])", "lights",
       "one light per scene"},
  };
  for (const Case& c : cases) {
    const std::string path =
        test::writeTempFile("bad_point_light.json", R"({"objects":[{"shape":"box"}],)" + c.json + "}");
    std::string error;
    try {
      loadScene(path, test::kAssets);
    } catch (const SceneError& e) {
      error = e.what();
    }
    EXPECT_EQ(error.rfind(path, 0), 0u) << c.json << " -> " << error;
    EXPECT_NE(error.find(c.field), std::string::npos) << c.json << " -> " << error;
    EXPECT_NE(error.find(c.words), std::string::npos) << c.json << " -> " << error;
  }
}

// The ball's shadow from a point light at height H over its centre is a disk of radius
// H tan(asin(r / (H - h))): the cone from the light tangent to the ball. Checked at 2 % inside
// and outside its rim, for a close and a far light.
TEST(PointLight, ReferenceShadowIsTheTangentConesDisk) {
  for (float height : {2.0f, 6.0f, 50.0f}) {
    const Scene scene = ballUnderPoint(height);
    const ReferenceTracer tracer(scene);
    const float rim = height * std::tan(std::asin(0.5f / (height - 1.0f)));
    for (float angle : {0.0f, 1.3f, 2.9f, 4.4f}) {
      const glm::vec3 dir(std::cos(angle), 0.0f, std::sin(angle));
      EXPECT_FALSE(tracer.pointLit(dir * (rim * 0.98f), {0, 1, 0})) << "height " << height << " angle " << angle;
      EXPECT_TRUE(tracer.pointLit(dir * (rim * 1.02f), {0, 1, 0})) << "height " << height << " angle " << angle;
    }
    EXPECT_FALSE(tracer.pointLit({0, 0, 0}, {0, 1, 0}));
    EXPECT_TRUE(tracer.pointLit({15, 0, 0}, {0, 1, 0}));
  }
}

// Beyond its range a point light lights nothing; a sphere light's penumbra is partial.
TEST(PointLight, ReferenceRangeAndRadius) {
  const Scene ranged = ballUnderPoint(3.0f, R"(,"range":5)");
  const ReferenceTracer tracer(ranged);
  EXPECT_TRUE(tracer.pointLit({3.9f, 0, 0}, {0, 1, 0}));   // distance 4.92
  EXPECT_FALSE(tracer.pointLit({4.1f, 0, 0}, {0, 1, 0}));  // distance 5.08
  const Scene soft = ballUnderPoint(3.0f, R"(,"radius":0.2)");
  const ReferenceTracer softTracer(soft);
  GroundRow row({{0, 0, 0}, {3 * std::tan(std::asin(0.25f)), 0, 0}, {10, 0, 0}});
  ReferenceOptions options;
  options.lightSamples = 256;
  const std::vector<float> v = softTracer.visibility(row.view(), options);
  EXPECT_EQ(v[0], 0.0f) << "umbra under the ball";
  EXPECT_GT(v[1], 0.2f) << "the rim of the point light's shadow is in the penumbra";
  EXPECT_LT(v[1], 0.8f);
  EXPECT_EQ(v[2], 1.0f);
}

LayoutInput inputFor(const Scene& scene, const Camera& cam, const ParamSet& params, float aspect) {
  LayoutInput in;
  in.scene = &scene;
  in.cameraView = cameraView(cam);
  in.cameraProj = cameraProjection(cam, aspect);
  in.params = &params;
  return in;
}

// Points inside the camera frustum and the scene's bounds, deterministic.
std::vector<glm::vec3> visibleSamples(const LayoutInput& in, const Bounds& b) {
  std::vector<glm::vec3> out;
  const glm::mat4 inv = glm::inverse(in.cameraProj * in.cameraView);
  for (int i = 0; i < 4000; ++i) {
    const glm::vec3 ndc(std::fmod(i * 0.6180339f, 1.0f) * 2 - 1, std::fmod(i * 0.7548776f, 1.0f) * 2 - 1,
                        std::fmod(i * 0.5698403f, 1.0f) * 2 - 1);
    const glm::vec4 w = inv * glm::vec4(ndc, 1.0f);
    const glm::vec3 p = glm::vec3(w) / w.w;
    if (glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max))) out.push_back(p);
  }
  return out;
}

int dominantFace(const glm::vec3& d) {
  int best = 0;
  for (int f = 1; f < 6; ++f)
    if (glm::dot(d, cubeFaces()[f].axis) > glm::dot(d, cubeFaces()[best].axis)) best = f;
  return best;
}

// Every visible receiver falls inside the fitted window of the face it reads, and no face the
// layout leaves undrawn holds one; looking away from the lamp needs fewer faces than six.
TEST(CubeLayout, EveryVisibleReceiverIsInItsFacesWindowAndUndrawnFacesHoldNone) {
  const Scene scene = loadScene("street", test::kAssets);
  ParamSet params = makeTechnique("cube", {}).params;
  const Bounds bounds = scene.boundsAt(0.0);
  int fewest = 6;
  for (const Camera& cam : scene.cameras) {
    const LayoutInput in = inputFor(scene, cam, params, 16.0f / 9.0f);
    const CubeViews v = cubeViews(scene.light, in);
    ASSERT_EQ(v.space.views.size(), 6u);
    fewest = std::min(fewest, v.neededCount());
    const std::vector<glm::vec3> samples = visibleSamples(in, bounds);
    ASSERT_GT(samples.size(), 100u) << cam.name;
    for (const glm::vec3& p : samples) {
      const int f = dominantFace(p - scene.light.position);
      ASSERT_TRUE(v.needed[f]) << cam.name << ": a visible point in undrawn face " << f;
      glm::vec3 uv;
      float depth = 0.0f;
      ASSERT_TRUE(mapPointOf(p, v.space.views[f], uv, depth)) << cam.name;
      EXPECT_GE(uv.x, -1e-3f) << cam.name << " face " << f;
      EXPECT_LE(uv.x, 1.001f) << cam.name << " face " << f;
      EXPECT_GE(uv.y, -1e-3f) << cam.name << " face " << f;
      EXPECT_LE(uv.y, 1.001f) << cam.name << " face " << f;
      EXPECT_GE(depth, -1e-3f);
      EXPECT_LE(depth, 1.001f);
    }
  }
  EXPECT_LT(fewest, 6) << "street's 'away' camera looks away from the lamp";
}

}  // namespace
}  // namespace sl
