// Point lights without a GPU: the scene format, the reference against shadows computed by hand,
// and the cube layout's faces (every visible receiver inside its face's fitted window; faces the
// view does not need are not drawn).
#include "part/light_frame.h"
#include "point/light_faces.h"
#include "reference/reference.h"
#include "tests/assets_dir.h"
#include "tests/gl_test_util.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <map>

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

std::string seventeenLights() {
  std::string list;
  for (int i = 0; i < 17; ++i) list += std::string(i ? "," : "") + R"({"type":"point","position":[0,2,0]})";
  return list;
}

// A point light and a directional one in one list; the first shadowed light is the one the
// techniques' views and the visibility metrics show, the others follow in the file's order.
TEST(PointLight, ALightListKeepsEveryLightInOrder) {
  const Scene s = loadScene(test::writeTempFile("point_lights_list.json", R"({"objects":[{"shape":"box"}],
      "lights":[{"type":"spot","position":[0,5,0],"direction":[0,-1,0],"shadow":false},
                {"type":"point","position":[1,2,3]},
                {"type":"directional","direction":[0,-1,0]}]})"),
                            test::kAssets);
  EXPECT_EQ(s.light.type, Light::Type::Point);
  EXPECT_TRUE(s.light.shadow);
  ASSERT_EQ(s.otherLights.size(), 2u);
  EXPECT_EQ(s.otherLights[0].type, Light::Type::Spot);
  EXPECT_FALSE(s.otherLights[0].shadow);
  EXPECT_EQ(s.otherLights[1].type, Light::Type::Directional);
  EXPECT_TRUE(s.otherLights[1].shadow);
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
      {R"("lights":[{"type":"point","position":[0,2,0],"shadow":false}])", "lights", "no light casts shadows"},
      {R"("lights":[{"type":"point","position":[0,2,0],"shadow":1}])", "lights[0].shadow", "true or false"},
      {R"("light":{"type":"point","position":[0,2,0],"shadow":false})", "light.shadow", "must cast shadows"},
      {R"("lights":[)" + seventeenLights() + "]", "lights", "at most 16"},
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

// The reference traces toward another of the scene's lights when asked (ReferenceOptions::light,
// what the metrics of a scene of several lights use): the ball's shadow moves with the light.
// From (10, 3, 0) the ray through the ball's centre (0, 1, 0) meets the ground at x = -5.
TEST(PointLight, ReferenceTracesTowardTheLightItIsGiven) {
  const Scene scene = ballUnderPoint(3.0f);
  const ReferenceTracer tracer(scene);
  const std::vector<float> position = {0, 0, 0, 1, -5, 0, 0, 1};
  const std::vector<float> normal = {0, 1, 0, 0, 0, 1, 0, 0};
  const GBufferView g{2, 1, position.data(), normal.data()};
  const std::vector<float> own = tracer.visibility(g, {});
  EXPECT_EQ(own, (std::vector<float>{0.0f, 1.0f}));
  Light other = scene.light;
  other.position = {10, 3, 0};
  ReferenceOptions options;
  options.light = &other;
  EXPECT_EQ(tracer.visibility(g, options), (std::vector<float>{1.0f, 0.0f}));
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
  for (int i = 0; i < 20000; ++i) {
    const glm::vec3 ndc(std::fmod(i * 0.6180339f, 1.0f) * 2 - 1, std::fmod(i * 0.7548776f, 1.0f) * 2 - 1,
                        std::fmod(i * 0.5698403f, 1.0f) * 2 - 1);
    const glm::vec4 w = inv * glm::vec4(ndc, 1.0f);
    const glm::vec3 p = glm::vec3(w) / w.w;
    if (glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max))) out.push_back(p);
  }
  return out;
}

// The atlas's squares: inside the layer, apart from each other, none for a need of 0, larger for
// a larger need, and filling a good part of the layer; extreme needs still fit.
TEST(LightFaces, AtlasSquaresFitTheLayerApartAndFollowTheNeeds) {
  for (const std::vector<double>& needs : std::vector<std::vector<double>>{
           {0.3, 0.1, 0.0, 0.05, 0.4, 0.01}, {1, 1, 1, 1, 1, 1}, {1e-4, 1, 0, 0, 0, 1e-4}, {0.5}}) {
    const int size = 1000;
    const std::vector<glm::ivec4> sq = atlasSquares(needs, size, 24);
    ASSERT_EQ(sq.size(), needs.size());
    long long used = 0;
    for (size_t i = 0; i < sq.size(); ++i) {
      if (needs[i] <= 0.0) {
        EXPECT_EQ(sq[i].z, 0) << i;
        continue;
      }
      EXPECT_GE(sq[i].z, 24) << i;
      EXPECT_EQ(sq[i].z % 8, 0) << i;
      EXPECT_GE(sq[i].x, 0);
      EXPECT_GE(sq[i].y, 0);
      EXPECT_LE(sq[i].x + sq[i].z, size);
      EXPECT_LE(sq[i].y + sq[i].w, size);
      used += static_cast<long long>(sq[i].z) * sq[i].w;
      for (size_t j = 0; j < i; ++j) {
        const bool apart = sq[i].x + sq[i].z <= sq[j].x || sq[j].x + sq[j].z <= sq[i].x ||
                           sq[i].y + sq[i].w <= sq[j].y || sq[j].y + sq[j].w <= sq[i].y;
        EXPECT_TRUE(apart || sq[j].z == 0) << i << " overlaps " << j;
      }
      for (size_t j = 0; j < sq.size(); ++j)
        if (needs[j] > needs[i]) EXPECT_GE(sq[j].z, sq[i].z) << j << " needs more than " << i;
    }
    EXPECT_GE(used, static_cast<long long>(size) * size / 3) << "the squares fill a third of the layer or more";
  }
  // A layer too small for the smallest side asked still gets a square for every need.
  const std::vector<glm::ivec4> tiny = atlasSquares({1, 1, 1, 1, 1, 1}, 64, 24);
  for (const glm::ivec4& s : tiny) EXPECT_GE(s.z, 8);
}

// Held squares: kept while every need stays within the band of the one they were sized for
// (measured from there, so a slow drift is followed), sized anew beyond it, when a face starts or
// stops being needed, when the layer's size changes, and every frame with a band of 1.
TEST(LightFaces, AtlasSquaresAreHeldWhileTheNeedsStayWithinTheBand) {
  const std::vector<double> first = {0.3, 0.1, 0.0, 0.05, 0.4, 0.01};
  AtlasHold hold;
  const std::vector<glm::ivec4> sized = heldAtlasSquares(first, 1000, 24, 1.5, hold);
  EXPECT_EQ(sized, atlasSquares(first, 1000, 24));
  std::vector<double> drift = first;
  for (double& n : drift) n *= 1.3;  // every face 1.3x: within 1.5
  drift[1] /= 1.3 * 1.3;             // one 1/1.3: still within
  EXPECT_EQ(heldAtlasSquares(drift, 1000, 24, 1.5, hold), sized);
  EXPECT_NE(atlasSquares(drift, 1000, 24), sized) << "the instrument: sized anew, the squares differ";
  std::vector<double> far = drift;
  far[4] = first[4] * 1.6;  // beyond 1.5 of the need it was sized for (1.23x the last frame's)
  const std::vector<glm::ivec4> resized = heldAtlasSquares(far, 1000, 24, 1.5, hold);
  EXPECT_EQ(resized, atlasSquares(far, 1000, 24));
  EXPECT_EQ(hold.needs, far);
  std::vector<double> newFace = far;
  newFace[2] = 0.02;  // a face now needed
  EXPECT_GT(heldAtlasSquares(newFace, 1000, 24, 1.5, hold)[2].z, 0);
  EXPECT_EQ(heldAtlasSquares(newFace, 500, 24, 1.5, hold), atlasSquares(newFace, 500, 24)) << "a new layer size";
  std::vector<double> nudged = newFace;
  nudged[0] *= 1.01;
  EXPECT_EQ(heldAtlasSquares(nudged, 500, 24, 1.0, hold), atlasSquares(nudged, 500, 24)) << "band 1: never held";
}

// Along street's `walk` (2 s at 30 fps) the held squares change seldom, and the faces' texel
// sizes with them (the map's shimmer, the bench's world flicker: docs in atlas.md); sized anew
// every frame they change many times.
TEST(LightFaces, AtlasSquaresHeldAlongAWalkChangeSeldom) {
  const Scene scene = loadScene("street", test::kAssets);
  const CameraPath* walk = scene.findPath("walk");
  ASSERT_NE(walk, nullptr);
  std::map<double, int> changes;
  for (double band : {1.0, 1.5}) {
    ParamSet params = makeTechnique("cube-atlas", {}).params;
    params.set("atlas.hold", band);
    AtlasHold hold;
    std::vector<glm::ivec4> last;
    for (int frame = 0; frame < 60; ++frame) {
      const Camera cam = walk->sample(float(frame) / 30.0f, scene.cameras.front());
      const FaceViews v =
          atlasFaceViews(cubeFaceSet(), scene.light, inputFor(scene, cam, params, 16.0f / 9.0f), 4, nullptr, &hold);
      std::vector<glm::ivec4> rects;
      for (const LightView& view : v.space.views) rects.push_back(view.atlasRect);
      changes[band] += frame > 0 && rects != last ? 1 : 0;
      last = rects;
    }
  }
  std::printf("square changes along walk: sized anew %d, held %d\n", changes[1.0], changes[1.5]);
  EXPECT_LE(changes[1.5], 3);
  EXPECT_GE(changes[1.0], 10) << "the instrument: the needs do move along the walk";
}

// Every direction in the view lands in its nearest face's square of the atlas, inside the border.
TEST(LightFaces, AtlasFacesReadTheirOwnSquare) {
  const Scene scene = loadScene("street", test::kAssets);
  ParamSet params = makeTechnique("cube-atlas", {}).params;
  params.set("shadowmap.size", 600);
  const LayoutInput in = inputFor(scene, scene.cameras.front(), params, 16.0f / 9.0f);
  const int border = 4;
  const FaceViews v = atlasFaceViews(cubeFaceSet(), scene.light, in, border);
  EXPECT_EQ(v.space.layerCount(), 1);
  EXPECT_TRUE(v.space.sharesLayers());
  EXPECT_FALSE(v.space.packed());
  const glm::mat4 toWorld = glm::inverse(in.cameraProj * in.cameraView);
  int checked = 0;
  for (int y = 0; y < 24; ++y)
    for (int x = 0; x < 40; ++x) {
      // A point on the ground (y = 0) under pixel (x, y), if the ray reaches it.
      const glm::vec2 ndc((x + 0.5f) / 20.0f - 1.0f, (y + 0.5f) / 12.0f - 1.0f);
      glm::vec4 a = toWorld * glm::vec4(ndc, -1.0f, 1.0f), b = toWorld * glm::vec4(ndc, 1.0f, 1.0f);
      const glm::vec3 p0 = glm::vec3(a) / a.w, p1 = glm::vec3(b) / b.w;
      if (!((p0.y > 0.0f) != (p1.y > 0.0f))) continue;
      const glm::vec3 p = p0 + (p1 - p0) * (p0.y / (p0.y - p1.y));
      if (std::abs(p.x) > 20.0f || std::abs(p.z) > 20.0f) continue;
      const int f = nearestFace(cubeFaceSet(), p - scene.light.position);
      ASSERT_TRUE(v.needed[size_t(f)]) << "a visible point's face is drawn";
      glm::vec3 uv;
      float depth = 0.0f;
      ASSERT_TRUE(mapPointOf(p, v.space.views[size_t(f)], uv, depth));
      const glm::ivec4 r = v.space.views[size_t(f)].atlasRect;
      const glm::vec2 texel = glm::vec2(uv) * 600.0f;
      EXPECT_GE(texel.x, r.x + border - 0.5f) << "face " << f;
      EXPECT_LE(texel.x, r.x + r.z - border + 0.5f) << "face " << f;
      EXPECT_GE(texel.y, r.y + border - 0.5f) << "face " << f;
      EXPECT_LE(texel.y, r.y + r.w - border + 0.5f) << "face " << f;
      ++checked;
    }
  EXPECT_GT(checked, 200);
}

// The side of the packed triangle q a map point (uv) is on, as shaders/common/light_views.glsl
// computes it: both >= 0 inside.
glm::vec2 packedSides(glm::vec2 uv, int q) {
  const glm::vec2 n = uv * 2.0f - 1.0f;
  const glm::vec2 p = q == 1 ? glm::vec2(-n.y, n.x) : q == 2 ? -n : q == 3 ? glm::vec2(n.y, -n.x) : n;
  return {p.y - p.x, p.y + p.x};
}

// Liao's packing: every direction lands in its nearest face's triangle of the one layer, at
// least the guard band inside its sides (the region is mapped onto the inset triangle), and the
// four triangles tile the layer; a direction a little past a face's edge (into the neighbour's
// region) still lands in that face's drawn triangle when it is within the guard band. Rolled too.
TEST(LightFaces, PackedTetrahedronKeepsEachFaceInItsTriangleWithAGuardBand) {
  const Scene scene = loadScene(test::writeTempFile("packed_faces_" + std::to_string(::getpid()) + ".json", R"({
    "objects":[{"name":"room","shape":"box","size":[40,40,40]}],
    "light":{"type":"point","position":[0.3,0.2,0.1]},
    "cameras":[{"position":[0.3,0.2,15.1],"target":[0.3,0.2,0.1],"fov_deg":10}]})"),
                                test::kAssets);
  ParamSet params = makeTechnique("tetrahedron-packed", {}).params;
  params.set("shadowmap.size", 512);
  const float guard = 8.0f, guardUv = guard / 512.0f;
  for (float roll : {0.0f, 0.3f}) {
    LayoutInput in = inputFor(scene, scene.cameras.front(), params, 1.0f);
    in.jitter.rotationRad = roll;
    const FaceViews v = packedTetrahedronViews(scene.light, in, guard);
    ASSERT_EQ(v.space.views.size(), 4u);
    EXPECT_EQ(v.space.layerCount(), 1);
    EXPECT_TRUE(v.space.packed());
    float nearestSide = 1e9f;
    for (int i = 0; i < 4000; ++i) {
      const float z = 1.0f - 2.0f * (i + 0.5f) / 4000.0f, r = std::sqrt(1.0f - z * z), a = 2.39996323f * i;
      const glm::vec3 d(r * std::cos(a), z, r * std::sin(a));
      const int f = nearestFace(tetrahedronFaceSet(), d);
      glm::vec3 uv;
      float depth = 0.0f;
      ASSERT_TRUE(mapPointOf(scene.light.position + d * 0.5f, v.space.views[size_t(f)], uv, depth)) << i;
      EXPECT_EQ(uv.z, 0.0f) << "every face reads layer 0";
      // Sides in uv units times 1/sqrt(2)... the distance to a diagonal is |side| / sqrt(2) in NDC,
      // |side| / (2 sqrt(2)) in uv.
      const glm::vec2 sides = packedSides(glm::vec2(uv), f) / (2.0f * std::sqrt(2.0f));
      nearestSide = std::min({nearestSide, sides.x, sides.y});
      EXPECT_GE(std::min(sides.x, sides.y), guardUv * 0.99f) << "roll " << roll << " face " << f << " direction " << i;
      for (int other = 0; other < 4; ++other)
        if (other != f)
          EXPECT_LT(std::min(packedSides(glm::vec2(uv), other).x, packedSides(glm::vec2(uv), other).y), 0.0f);
    }
    // The band is used: some direction lies within two guard widths of its triangle's side.
    EXPECT_LT(nearestSide, 2.0f * guardUv) << "roll " << roll;
    // Just past face 0's edge toward face 1 (the midpoint of their shared edge, turned 0.2
    // texels' worth past it): in face 0's view still inside its drawn triangle.
    const LightFace& f0 = tetrahedronFaceSet().faces[0];
    const glm::vec3 edgeMid = glm::normalize(f0.corners[0] + f0.corners[1]);
    const glm::vec3 past =
        glm::normalize(edgeMid + 0.002f * glm::normalize(tetrahedronFaceSet().faces[1].axis - f0.axis));
    glm::vec3 uv;
    float depth = 0.0f;
    ASSERT_TRUE(mapPointOf(scene.light.position + past * 0.5f, v.space.views[0], uv, depth));
    const glm::vec2 sides = packedSides(glm::vec2(uv), 0);
    EXPECT_GE(std::min(sides.x, sides.y), 0.0f) << "a tap just past the edge reads face 0's own drawn band";
  }
}

// Every direction from the light falls in exactly one face's region, inside that face's whole
// (unfitted) window: the faces cover the sphere and the pick in the shader is the face that
// holds the point. Checked for both face sets, also with a rolled view (the jitter's rotation).
TEST(LightFaces, EveryDirectionIsInsideTheWindowOfItsNearestFace) {
  // A light amid a large box, a camera 15 units off that sees the whole ball of radius 0.5
  // around it: every sample below is a visible receiver inside the scene's bounds.
  const Scene scene = loadScene(test::writeTempFile("light_faces_" + std::to_string(::getpid()) + ".json", R"({
    "objects":[{"name":"room","shape":"box","size":[40,40,40]}],
    "light":{"type":"point","position":[0.3,0.2,0.1]},
    "cameras":[{"position":[0.3,0.2,15.1],"target":[0.3,0.2,0.1],"fov_deg":10}]})"),
                                test::kAssets);
  ParamSet params = makeTechnique("cube", {}).params;
  params.set("shadowmap.size", 64);
  for (const FaceSet* set : {&cubeFaceSet(), &tetrahedronFaceSet()}) {
    for (float roll : {0.0f, 0.3f}) {
      LayoutInput in = inputFor(scene, scene.cameras.front(), params, 1.0f);
      in.jitter.rotationRad = roll;
      const FaceViews v = faceViews(*set, scene.light, in);
      ASSERT_EQ(v.space.views.size(), set->faces.size());
      for (int i = 0; i < 2000; ++i) {
        // Fibonacci sphere: directions spread evenly, corners and edges of the faces included.
        const float z = 1.0f - 2.0f * (i + 0.5f) / 2000.0f, r = std::sqrt(1.0f - z * z), a = 2.39996323f * i;
        const glm::vec3 d(r * std::cos(a), z, r * std::sin(a));
        const int f = nearestFace(*set, d);
        glm::vec3 uv;
        float depth = 0.0f;
        const glm::vec3 p = scene.light.position + d * 0.5f;
        ASSERT_TRUE(mapPointOf(p, v.space.views[f], uv, depth)) << set->name << " direction " << i;
        EXPECT_GE(uv.x, -1e-3f) << set->name << " roll " << roll << " face " << f;
        EXPECT_LE(uv.x, 1.001f) << set->name << " roll " << roll << " face " << f;
        EXPECT_GE(uv.y, -1e-3f) << set->name << " roll " << roll << " face " << f;
        EXPECT_LE(uv.y, 1.001f) << set->name << " roll " << roll << " face " << f;
      }
    }
  }
}

// A tetrahedron's faces are a regular tetrahedron's: axes at dot -1/3, each region's corners at
// dot 1/3 with its axis (70.53 degrees off it).
TEST(LightFaces, TetrahedronFacesAreRegular) {
  const FaceSet& t = tetrahedronFaceSet();
  ASSERT_EQ(t.faces.size(), 4u);
  for (size_t i = 0; i < 4; ++i) {
    EXPECT_NEAR(glm::length(t.faces[i].axis), 1.0f, 1e-5f);
    ASSERT_EQ(t.faces[i].corners.size(), 3u);
    for (const glm::vec3& c : t.faces[i].corners) EXPECT_NEAR(glm::dot(c, t.faces[i].axis), 1.0f / 3.0f, 1e-5f);
    for (size_t j = i + 1; j < 4; ++j) EXPECT_NEAR(glm::dot(t.faces[i].axis, t.faces[j].axis), -1.0f / 3.0f, 1e-5f);
  }
  EXPECT_EQ(nearestFace(t, {0, -1, 0}), 0);
}

// Every visible receiver falls inside the fitted window of the face it reads, and no face the
// layout leaves undrawn holds one; looking away from the lamp needs fewer faces than all.
TEST(LightFaces, EveryVisibleReceiverIsInItsFacesWindowAndUndrawnFacesHoldNone) {
  const Scene scene = loadScene("street", test::kAssets);
  ParamSet params = makeTechnique("cube", {}).params;
  const Bounds bounds = scene.boundsAt(0.0);
  for (const FaceSet* set : {&cubeFaceSet(), &tetrahedronFaceSet()}) {
    int fewest = static_cast<int>(set->faces.size());
    for (const Camera& cam : scene.cameras) {
      const LayoutInput in = inputFor(scene, cam, params, 16.0f / 9.0f);
      const FaceViews v = faceViews(*set, scene.light, in);
      ASSERT_EQ(v.space.views.size(), set->faces.size());
      fewest = std::min(fewest, v.neededCount());
      const std::vector<glm::vec3> samples = visibleSamples(in, bounds);
      ASSERT_GT(samples.size(), 100u) << cam.name;
      for (const glm::vec3& p : samples) {
        const int f = nearestFace(*set, p - scene.light.position);
        ASSERT_TRUE(v.needed[f]) << set->name << " " << cam.name << ": a visible point in undrawn face " << f;
        glm::vec3 uv;
        float depth = 0.0f;
        ASSERT_TRUE(mapPointOf(p, v.space.views[f], uv, depth)) << cam.name;
        EXPECT_GE(uv.x, -1e-3f) << set->name << " " << cam.name << " face " << f;
        EXPECT_LE(uv.x, 1.001f) << set->name << " " << cam.name << " face " << f;
        EXPECT_GE(uv.y, -1e-3f) << set->name << " " << cam.name << " face " << f;
        EXPECT_LE(uv.y, 1.001f) << set->name << " " << cam.name << " face " << f;
        EXPECT_GE(depth, -1e-3f);
        EXPECT_LE(depth, 1.001f);
      }
    }
    EXPECT_LT(fewest, static_cast<int>(set->faces.size())) << set->name << ": street's 'away' camera looks away";
  }
}

}  // namespace
}  // namespace sl
