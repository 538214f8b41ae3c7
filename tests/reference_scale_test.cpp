// The ray-traced reference against shadows computed by hand in double precision, on rasterized
// G-buffers (the points the reference really traces from), at small and large scale and under
// a grazing sun: a sphere's shadow on a plane is an ellipse, a box's is a slab test.
#include "gl_test_util.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cmath>
#include <functional>
#include <string>

namespace sl {
namespace {

// What the hand computation says of one ground point: certainly lit, certainly shadowed, or
// too close to the shadow's edge for the positions' precision to decide.
enum class Truth { Lit, Shadowed, Undecided };

struct Tally {
  long long ground = 0, lit = 0, shadowed = 0, undecided = 0, wrongLit = 0, wrongShadowed = 0;
};

std::string describe(const Tally& t) {
  return "ground " + std::to_string(t.ground) + ", lit " + std::to_string(t.lit) + ", shadowed " +
         std::to_string(t.shadowed) + ", undecided " + std::to_string(t.undecided) + ", traced shadowed where lit " +
         std::to_string(t.wrongLit) + ", traced lit where shadowed " + std::to_string(t.wrongShadowed);
}

// A directional light `elevationDeg` above the horizon, light travelling toward +x/-z.
std::string sunDirection(double elevationDeg) {
  const double e = elevationDeg * M_PI / 180.0;
  char buffer[128];
  std::snprintf(buffer, sizeof buffer, "[%.17g, %.17g, %.17g]", std::cos(e) * 0.8, -std::sin(e), -std::cos(e) * 0.6);
  return buffer;
}

// Renders `sceneJson`'s first camera, traces the reference from the G-buffer and compares each
// pixel of the instance named "ground" (the plane y = 0) with `truth(point, towardLight)`.
Tally traceAndCompare(const std::string& name, const std::string& sceneJson,
                      const std::function<Truth(const glm::dvec3&, const glm::dvec3&)>& truth) {
  test::GlHarness h;
  Scene scene = loadScene(test::writeTempFile(name + ".json", sceneJson), defaultAssetsDir());
  int ground = -1;
  for (size_t i = 0; i < scene.instances.size(); ++i)
    if (scene.instances[i].name == "ground") ground = static_cast<int>(i);
  EXPECT_GE(ground, 0);
  const test::Frame f = test::renderOnce(h, scene, "standard", {}, 160, 96);
  ReferenceTracer tracer(scene);
  const std::vector<float> reference = tracer.visibility(f.gbuffer(), ReferenceOptions{});
  const glm::dvec3 towardLight = -glm::dvec3(glm::normalize(scene.light.direction));

  Tally t;
  for (size_t i = 0; i < reference.size(); ++i) {
    if (f.position[4 * i + 3] < 0.5f || f.surface[4 * i] != static_cast<uint32_t>(ground + 1)) continue;
    ++t.ground;
    // The plane is y = 0 exactly; the rasterizer's position is off it by its rounding only.
    const glm::dvec3 p(f.position[4 * i], 0.0, f.position[4 * i + 2]);
    const Truth expected = truth(p, towardLight);
    const bool tracedLit = reference[i] > 0.5f;
    if (expected == Truth::Undecided) {
      ++t.undecided;
    } else if (expected == Truth::Lit) {
      ++t.lit;
      t.wrongLit += tracedLit ? 0 : 1;
    } else {
      ++t.shadowed;
      t.wrongShadowed += tracedLit ? 1 : 0;
    }
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
  return t;
}

// How far from its edge a shadow must be before the positions' precision cannot move it: a
// float coordinate of magnitude `scale` is off by about 2^-24 * scale; 2^-18 allows 64 times that.
double edgeMargin(double scale) { return scale / 262144.0; }

// Ellipse test: the ray from p toward the light passes within `radius` of the centre. The UV
// sphere of `segments` lies between the inscribed radius r cos^2(pi / segments) and r.
std::function<Truth(const glm::dvec3&, const glm::dvec3&)> sphereShadow(glm::dvec3 centre, double radius, int segments,
                                                                        double scale) {
  const double inner = radius * std::pow(std::cos(M_PI / segments), 2.0);
  const double margin = edgeMargin(scale);
  return [=](const glm::dvec3& p, const glm::dvec3& l) {
    const glm::dvec3 v = centre - p;
    const double along = glm::dot(v, l);
    if (along <= 0.0) return Truth::Lit;
    const double distance = std::sqrt(std::max(glm::dot(v, v) - along * along, 0.0));
    if (distance < inner - margin) return Truth::Shadowed;
    if (distance > radius + margin) return Truth::Lit;
    return Truth::Undecided;
  };
}

// Slab test of the ray p + t l (t > 0) against the axis-aligned box [lo, hi] grown by `grow`.
bool rayHitsBox(const glm::dvec3& p, const glm::dvec3& l, glm::dvec3 lo, glm::dvec3 hi, double grow) {
  lo -= glm::dvec3(grow);
  hi += glm::dvec3(grow);
  double t0 = 0.0, t1 = 1e300;
  for (int a = 0; a < 3; ++a) {
    if (std::abs(l[a]) < 1e-300) {
      if (p[a] < lo[a] || p[a] > hi[a]) return false;
      continue;
    }
    double ta = (lo[a] - p[a]) / l[a], tb = (hi[a] - p[a]) / l[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

std::function<Truth(const glm::dvec3&, const glm::dvec3&)> boxShadow(glm::dvec3 lo, glm::dvec3 hi, double scale) {
  const double margin = edgeMargin(scale);
  return [=](const glm::dvec3& p, const glm::dvec3& l) {
    if (rayHitsBox(p, l, lo, hi, -margin)) return Truth::Shadowed;
    if (!rayHitsBox(p, l, lo, hi, margin)) return Truth::Lit;
    return Truth::Undecided;
  };
}

// A camera `side` metres to the side of the light's path (not behind the caster) and `height`
// above the ground, looking at `target`.
std::string cameraBeside(const glm::dvec3& target, double side, double height, double nearPlane) {
  const glm::dvec3 position = target + glm::dvec3(0.6, 0.0, 0.8) * side + glm::dvec3(0.0, height, 0.0);
  char buffer[256];
  std::snprintf(buffer, sizeof buffer,
                R"({"name": "c", "position": [%.9g, %.9g, %.9g], "target": [%.9g, %.9g, %.9g], "fov_deg": 60, )"
                R"("near": %.9g, "far": 3000})",
                position.x, position.y, position.z, target.x, target.y, target.z, nearPlane);
  return buffer;
}

std::string sceneText(const std::string& ground, const std::string& caster, const std::string& light,
                      const std::string& camera) {
  return R"({"objects": [)" + ground + ", " + caster + R"(], "light": {"type": "directional", "direction": )" + light +
         R"(}, "cameras": [)" + camera + "]}";
}

void expectTraced(const Tally& t, long long minShadowed, double maxUndecidedFraction) {
  SCOPED_TRACE(describe(t));
  std::printf("%s\n", describe(t).c_str());
  EXPECT_GT(t.shadowed, minShadowed);
  EXPECT_GT(t.lit, minShadowed);
  EXPECT_EQ(t.wrongLit, 0);
  EXPECT_EQ(t.wrongShadowed, 0);
  EXPECT_LT(static_cast<double>(t.undecided), maxUndecidedFraction * static_cast<double>(t.ground));
}

// The terrain case: a 0.3 m sphere resting on a 2 km ground, 900 m from the origin, where a
// float coordinate is good to 0.06 mm. The old offset (1e-4 x the scene diagonal = 0.28 m) lost
// this shadow entirely.
TEST(ReferenceScale, SphereOnTwoKilometreGroundCastsItsEllipse) {
  const std::string ground = R"({"name": "ground", "shape": "plane", "size": [2000, 2000], "subdivisions": 128})";
  const std::string sphere =
      R"({"name": "ball", "shape": "sphere", "radius": 0.3, "segments": 64, "transform": {"translate": [900, 0.3, 900]}})";
  const std::string camera = cameraBeside({900.34, 0, 899.74}, 0.9, 1.0, 0.05);
  const Tally t = traceAndCompare("scale_sphere_2km", sceneText(ground, sphere, sunDirection(35.0), camera),
                                  sphereShadow({900, 0.3, 900}, 0.3, 64, 1000.0));
  expectTraced(t, 500, 0.08);
}

// The same at room scale: a 1 cm ball on a 10 m floor.
TEST(ReferenceScale, CentimetreSphereOnTenMetreFloorCastsItsEllipse) {
  const std::string ground = R"({"name": "ground", "shape": "plane", "size": [10, 10], "subdivisions": 8})";
  const std::string sphere =
      R"({"name": "ball", "shape": "sphere", "radius": 0.01, "segments": 64, "transform": {"translate": [3, 0.01, -2]}})";
  const std::string camera = cameraBeside({3.011, 0, -2.008}, 0.03, 0.035, 0.002);
  const Tally t = traceAndCompare("scale_sphere_room", sceneText(ground, sphere, sunDirection(35.0), camera),
                                  sphereShadow({3, 0.01, -2}, 0.01, 64, 5.0));
  expectTraced(t, 500, 0.08);
}

// A box whose bottom edge is 1 cm above a 2 km ground: light passes through the gap, so the
// shadow starts 1 cm x cot(elevation) away from the box's footprint. Any lift of the ray origin
// over 1 cm closes the gap.
TEST(ReferenceScale, BoxOneCentimetreAboveTwoKilometreGround) {
  const std::string ground = R"({"name": "ground", "shape": "plane", "size": [2000, 2000], "subdivisions": 128})";
  const std::string box =
      R"({"name": "slab", "shape": "box", "size": [0.4, 0.2, 0.4], "transform": {"translate": [-700, 0.11, 650]}})";
  const std::string camera = cameraBeside({-699.76, 0, 649.82}, 0.6, 0.7, 0.02);
  const Tally t = traceAndCompare("scale_box_gap", sceneText(ground, box, sunDirection(20.0), camera),
                                  boxShadow({-700.2, 0.01, 649.8}, {-699.8, 0.21, 650.2}, 1000.0));
  expectTraced(t, 500, 0.08);
}

// A sun 0.05 degrees above the horizon over a 100 m ground: a lift of h moves the shadow's edge
// by h x cot(0.05 deg) = 1146 h, and the ground's N.L is 0.0009. The box rests on the ground
// (the contact shadow) and its shadow is over a kilometre long. A box, not a sphere: a polygonal
// sphere's shadow at this angle is only known to within its tessellation x 1146.
TEST(ReferenceScale, GrazingSunOverHundredMetreGround) {
  const std::string ground = R"({"name": "ground", "shape": "plane", "size": [100, 100], "subdivisions": 16})";
  const std::string box =
      R"({"name": "block", "shape": "box", "size": [1, 1, 1], "transform": {"translate": [-20, 0.5, 15]}})";
  const std::string camera = cameraBeside({-17.6, 0, 13.2}, 1.6, 1.4, 0.05);
  const Tally t = traceAndCompare("scale_grazing", sceneText(ground, box, sunDirection(0.05), camera),
                                  boxShadow({-20.5, 0, 14.5}, {-19.5, 1, 15.5}, 50.0));
  expectTraced(t, 500, 0.08);
}

// The contact shadow of a ball under that sun: near the ground the ray toward the sun is almost
// horizontal, so a lift of h makes it cut the ball over a chord of 2 sqrt(2 r h) (23 cm for the
// old 1.4 cm lift): a wide false shadow beside the contact point.
TEST(ReferenceScale, GrazingSunContactShadowOfABall) {
  const std::string ground = R"({"name": "ground", "shape": "plane", "size": [100, 100], "subdivisions": 16})";
  const std::string sphere =
      R"({"name": "ball", "shape": "sphere", "radius": 0.5, "segments": 64, "transform": {"translate": [-20, 0.5, 15]}})";
  const std::string camera = cameraBeside({-18.8, 0, 14.1}, 1.1, 0.7, 0.05);
  const Tally t = traceAndCompare("scale_grazing_ball", sceneText(ground, sphere, sunDirection(0.05), camera),
                                  sphereShadow({-20, 0.5, 15}, 0.5, 64, 50.0));
  expectTraced(t, 100, 0.08);
}

}  // namespace
}  // namespace sl
