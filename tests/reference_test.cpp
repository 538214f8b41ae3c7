// The ray-traced reference against analytic shadows of scenes built in code.
// Only the inline parts of scene.h are used, so this does not depend on the scene loader.
#include "reference/reference.h"

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <thread>
#include <vector>

namespace sl {
namespace {

// A G-buffer built from explicit points, stored the way the rasterizer reads it back.
struct TestGBuffer {
  int width = 0, height = 0;
  std::vector<float> position, normal;
  TestGBuffer(int w, int h) : width(w), height(h), position(4 * w * h, 0.0f), normal(4 * w * h, 0.0f) {}
  void set(int x, int y, const glm::vec3& p, const glm::vec3& n) {
    const size_t i = 4 * (static_cast<size_t>(y) * width + x);
    position[i] = p.x, position[i + 1] = p.y, position[i + 2] = p.z, position[i + 3] = 1.0f;
    normal[i] = n.x, normal[i + 1] = n.y, normal[i + 2] = n.z;
  }
  GBufferView view() const { return GBufferView{width, height, position.data(), normal.data()}; }
};

// Closed axis-aligned box, 12 triangles.
Mesh boxMesh(const glm::vec3& lo, const glm::vec3& hi) {
  Mesh m;
  m.name = "box";
  for (int i = 0; i < 8; ++i) {
    m.positions.push_back({(i & 1) ? hi.x : lo.x, (i & 2) ? hi.y : lo.y, (i & 4) ? hi.z : lo.z});
    m.normals.push_back(glm::vec3(0.0f));
    m.uvs.push_back(glm::vec2(0.0f));
  }
  const uint32_t quads[6][4] = {{0, 2, 6, 4}, {1, 5, 7, 3}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 6, 7, 5}};
  for (const auto& q : quads) m.indices.insert(m.indices.end(), {q[0], q[1], q[2], q[0], q[2], q[3]});
  return m;
}

// Horizontal quad at height y over [x0,x1]x[z0,z1]; u runs with x, v with z.
Mesh quadMesh(float y, float x0, float x1, float z0, float z1) {
  Mesh m;
  m.name = "quad";
  m.positions = {{x0, y, z0}, {x1, y, z0}, {x1, y, z1}, {x0, y, z1}};
  m.normals.assign(4, glm::vec3(0, 1, 0));
  m.uvs = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  m.indices = {0, 1, 2, 0, 2, 3};
  return m;
}

void addInstance(Scene& scene, Mesh mesh, int material = 0) {
  mesh.material = material;
  scene.meshes.push_back(std::move(mesh));
  Instance inst;
  inst.name = scene.meshes.back().name;
  inst.mesh = static_cast<int>(scene.meshes.size()) - 1;
  scene.instances.push_back(inst);
}

const glm::vec3 kLightDir = glm::normalize(glm::vec3(-0.5f, -1.0f, -0.35f));

// Unit box standing on a ground plane, lit by a directional light.
Scene boxScene(float radius = 0.0f) {
  Scene scene;
  scene.materials.push_back(Material{});
  addInstance(scene, quadMesh(0.0f, -3.5f, 3.5f, -3.5f, 3.5f));
  addInstance(scene, boxMesh({-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}));
  scene.light.type = Light::Type::Directional;
  scene.light.direction = kLightDir;
  scene.light.radius = radius;
  return scene;
}

// ---- analytic shadow of the box: convex hull of its corners projected along the light ----

double cross2(const glm::dvec2& o, const glm::dvec2& a, const glm::dvec2& b) {
  return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> pts) {  // counter-clockwise
  std::sort(pts.begin(), pts.end(), [](auto& a, auto& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  std::vector<glm::dvec2> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && cross2(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  hull.resize(k - 1);
  return hull;
}

std::vector<glm::dvec2> boxShadowPolygon() {
  std::vector<glm::dvec2> projected;
  const glm::dvec3 d(kLightDir);
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 c((i & 1) ? 0.5 : -0.5, (i & 2) ? 1.0 : 0.0, (i & 4) ? 0.5 : -0.5);
    const double t = -c.y / d.y;  // walk along the light until y = 0
    projected.push_back({c.x + t * d.x, c.z + t * d.z});
  }
  return convexHull(projected);
}

// Signed distance to a counter-clockwise convex polygon's boundary: > 0 inside.
double insideDistance(const std::vector<glm::dvec2>& poly, const glm::dvec2& p) {
  double dist = 1e30;
  for (size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
    dist = std::min(dist, cross2(a, b, p) / glm::length(b - a));
  }
  return dist;
}

TEST(Reference, HardShadowMatchesProjectedHull) {
  const Scene scene = boxScene();
  const ReferenceTracer tracer(scene);
  const int n = 256;
  TestGBuffer g(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x)
      g.set(x, y, {-3.0f + 6.0f * (x + 0.5f) / n, 0.0f, -3.0f + 6.0f * (y + 0.5f) / n}, {0, 1, 0});
  ReferenceOptions options;
  const std::vector<float> vis = tracer.visibility(g.view(), options);
  ASSERT_EQ(vis.size(), static_cast<size_t>(n * n));

  const std::vector<glm::dvec2> poly = boxShadowPolygon();
  int shadowed = 0, mismatches = 0;
  for (int y = 0; y < n; ++y) {
    for (int x = 0; x < n; ++x) {
      const size_t i = static_cast<size_t>(y) * n + x;
      const glm::dvec2 p(g.position[4 * i], g.position[4 * i + 2]);
      const double dist = insideDistance(poly, p);
      const float expected = dist > 0 ? 0.0f : 1.0f;
      shadowed += expected == 0.0f;
      if (vis[i] != expected && std::abs(dist) > 1e-3) {
        ++mismatches;
        ADD_FAILURE() << "point (" << p.x << ", " << p.y << ") visibility " << vis[i] << ", expected " << expected
                      << " (distance to shadow boundary " << dist << ")";
      }
      if (mismatches > 10) return;
    }
  }
  EXPECT_GT(shadowed, 1000);  // the test really covers a shadow
}

TEST(Reference, BoxFacesLitAndFacingAway) {
  const Scene scene = boxScene();
  const ReferenceTracer tracer(scene);
  TestGBuffer g(4, 3);
  // Row 0: top face (lit). Row 1: -x face, facing away from the light. Row 2: +x face (lit).
  const float coords[4] = {-0.4f, -0.1f, 0.2f, 0.45f};
  for (int i = 0; i < 4; ++i) {
    g.set(i, 0, {coords[i], 1.0f, coords[3 - i]}, {0, 1, 0});
    g.set(i, 1, {-0.5f, 0.5f + 0.4f * coords[i], coords[i]}, {-1, 0, 0});
    g.set(i, 2, {0.5f, 0.5f + 0.4f * coords[i], coords[i]}, {1, 0, 0});
  }
  const std::vector<float> vis = tracer.visibility(g.view(), ReferenceOptions{});
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(vis[i], 1.0f) << "top face point " << i;
    EXPECT_EQ(vis[4 + i], 0.0f) << "back face point " << i;
    EXPECT_EQ(vis[8 + i], 1.0f) << "front face point " << i;
  }
  EXPECT_TRUE(tracer.pointLit({0.0f, 1.0f, 0.0f}, {0, 1, 0}));
  EXPECT_FALSE(tracer.pointLit({-0.6f, 0.0f, -0.35f}, {0, 1, 0}));
}

TEST(Reference, BackgroundPixelsAreZero) {
  const ReferenceTracer tracer(boxScene());
  TestGBuffer g(2, 1);
  g.set(0, 0, {2.0f, 0.0f, 2.0f}, {0, 1, 0});  // pixel 1 stays background (w = 0)
  const std::vector<float> vis = tracer.visibility(g.view(), ReferenceOptions{});
  EXPECT_EQ(vis[0], 1.0f);
  EXPECT_EQ(vis[1], 0.0f);
}

TEST(Reference, SoftShadowUmbraPenumbraLit) {
  const ReferenceTracer tracer(boxScene(0.05f));
  TestGBuffer g(3, 1);
  g.set(0, 0, {-0.6f, 0.0f, -0.35f}, {0, 1, 0});  // deep in the umbra
  g.set(1, 0, {2.0f, 0.0f, 2.0f}, {0, 1, 0});     // far outside
  g.set(2, 0, {-1.0f, 0.0f, -0.35f}, {0, 1, 0});  // on the hard shadow edge cast by the top edge
  ReferenceOptions options;
  options.lightSamples = 64;
  const std::vector<float> vis = tracer.visibility(g.view(), options);
  EXPECT_EQ(vis[0], 0.0f);
  EXPECT_EQ(vis[1], 1.0f);
  EXPECT_GT(vis[2], 0.2f);
  EXPECT_LT(vis[2], 0.8f);
}

TEST(Reference, SpotConeAndOcclusion) {
  Scene scene = boxScene();
  scene.light.type = Light::Type::Spot;
  scene.light.position = {0.0f, 5.0f, 0.0f};
  scene.light.direction = {0.0f, -1.0f, 0.0f};
  scene.light.fovDeg = 30.0f;
  const ReferenceTracer tracer(scene);
  TestGBuffer g(3, 1);
  g.set(0, 0, {0.8f, 0.0f, 0.0f}, {0, 1, 0});  // inside the cone, beside the box: lit
  g.set(1, 0, {0.3f, 1.0f, 0.0f}, {0, 1, 0});  // box top: lit
  g.set(2, 0, {2.0f, 0.0f, 2.0f}, {0, 1, 0});  // outside the 15 degree half-angle: unlit
  const std::vector<float> vis = tracer.visibility(g.view(), ReferenceOptions{});
  EXPECT_EQ(vis[0], 1.0f);
  EXPECT_EQ(vis[1], 1.0f);
  EXPECT_EQ(vis[2], 0.0f);
  EXPECT_FALSE(tracer.pointLit({0.55f, 0.0f, 0.0f}, {0, 1, 0}));  // the box edge shadows it
}

// A quad caster at y = 1 with a 2x2 texture, lit straight from above.
Scene alphaScene(bool alphaMask, bool splitRows) {
  Scene scene;
  Material material;
  material.baseColorTexture = 0;
  material.alphaMask = alphaMask;
  material.alphaCutoff = 0.5f;
  scene.materials.push_back(material);
  Texture tex;
  tex.name = "mask";
  tex.width = 2;
  tex.height = 2;
  tex.rgba.assign(16, 255);
  // splitRows: top row (row 0, small v) transparent. Otherwise: left column (small u) transparent.
  const int transparent[2] = {0, splitRows ? 1 : 2};
  for (int t : transparent) tex.rgba[4 * t + 3] = 0;
  scene.textures.push_back(tex);
  addInstance(scene, quadMesh(1.0f, -1.0f, 1.0f, -1.0f, 1.0f));
  scene.light.direction = {0.0f, -1.0f, 0.0f};
  return scene;
}

std::vector<float> quadrantVisibility(const Scene& scene) {
  const ReferenceTracer tracer(scene);
  TestGBuffer g(4, 1);
  g.set(0, 0, {-0.5f, 0.0f, -0.5f}, {0, 1, 0});  // u 0.25, v 0.25
  g.set(1, 0, {-0.5f, 0.0f, 0.5f}, {0, 1, 0});   // u 0.25, v 0.75
  g.set(2, 0, {0.5f, 0.0f, -0.5f}, {0, 1, 0});   // u 0.75, v 0.25
  g.set(3, 0, {0.5f, 0.0f, 0.5f}, {0, 1, 0});    // u 0.75, v 0.75
  return tracer.visibility(g.view(), ReferenceOptions{});
}

TEST(Reference, AlphaMaskLetsLightThroughHoles) {
  EXPECT_EQ(quadrantVisibility(alphaScene(true, false)), (std::vector<float>{1, 1, 0, 0}));
  EXPECT_EQ(quadrantVisibility(alphaScene(false, false)), (std::vector<float>{0, 0, 0, 0}));
  // Rows: v = 0 is the top row of the image (glTF convention), row 0 of Texture.rgba.
  EXPECT_EQ(quadrantVisibility(alphaScene(true, true)), (std::vector<float>{1, 0, 1, 0}));
  // baseColor.a scales the texture alpha: 0.4 * 255/255 < 0.5 cutoff, so everything is a hole.
  Scene faded = alphaScene(true, false);
  faded.materials[0].baseColor.a = 0.4f;
  EXPECT_EQ(quadrantVisibility(faded), (std::vector<float>{1, 1, 1, 1}));
}

TEST(Reference, DeterministicAcrossThreadCounts) {
  const ReferenceTracer tracer(boxScene(0.08f));
  const int n = 48;
  TestGBuffer g(n, n);
  for (int y = 0; y < n; ++y)
    for (int x = 0; x < n; ++x) g.set(x, y, {-1.5f + 2.0f * x / n, 0.0f, -1.5f + 2.0f * y / n}, {0, 1, 0});
  ReferenceOptions options;
  options.lightSamples = 16;
  options.threads = 1;
  const std::vector<float> one = tracer.visibility(g.view(), options);
  options.threads = 2;
  const std::vector<float> two = tracer.visibility(g.view(), options);
  EXPECT_EQ(one, two);
  EXPECT_TRUE(std::any_of(one.begin(), one.end(), [](float v) { return v > 0.0f && v < 1.0f; }));
}

TEST(Reference, ErrorsAreClear) {
  Scene empty;
  EXPECT_THROW({ ReferenceTracer tracer(empty); }, std::runtime_error);
  Scene broken = boxScene();
  broken.instances[0].mesh = 7;
  EXPECT_THROW({ ReferenceTracer tracer(broken); }, std::runtime_error);
}

// Not a timed assertion: prints build + trace time for docs/reference.md.
TEST(Reference, SpeedSphereOverPlane) {
  Scene scene;
  scene.materials.push_back(Material{});
  addInstance(scene, quadMesh(0.0f, -4.0f, 4.0f, -4.0f, 4.0f));
  Mesh sphere;
  sphere.name = "sphere";
  const int stacks = 224, slices = 224;  // 2 * 224 * 224 = 100352 triangles
  for (int i = 0; i <= stacks; ++i) {
    const float theta = 3.14159265f * i / stacks;
    for (int j = 0; j <= slices; ++j) {
      const float phi = 2.0f * 3.14159265f * j / slices;
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      sphere.positions.push_back(n + glm::vec3(0.0f, 1.3f, 0.0f));
      sphere.normals.push_back(n);
      sphere.uvs.push_back(glm::vec2(0.0f));
    }
  }
  for (int i = 0; i < stacks; ++i)
    for (int j = 0; j < slices; ++j) {
      const uint32_t a = i * (slices + 1) + j, b = a + slices + 1;
      sphere.indices.insert(sphere.indices.end(), {a, b, a + 1, a + 1, b, b + 1});
    }
  addInstance(scene, sphere);
  scene.light.direction = kLightDir;

  const int w = 640, h = 360;
  TestGBuffer g(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      g.set(x, y, {-3.5f + 7.0f * (x + 0.5f) / w, 0.0f, -2.0f + 4.0f * (y + 0.5f) / h}, {0, 1, 0});

  const auto start = std::chrono::steady_clock::now();
  const ReferenceTracer tracer(scene);
  const auto built = std::chrono::steady_clock::now();
  const std::vector<float> vis = tracer.visibility(g.view(), ReferenceOptions{});
  const auto done = std::chrono::steady_clock::now();
  auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
  const double lit = std::count(vis.begin(), vis.end(), 1.0f) * 100.0 / vis.size();
  std::printf(
      "[speed] %zu triangles, %dx%d hard shadows: build %.1f ms, trace %.1f ms, total %.1f ms "
      "(%u hardware threads, %.1f%% lit)\n",
      scene.meshes[1].indices.size() / 3 + 2, w, h, ms(start, built), ms(built, done), ms(start, done),
      std::thread::hardware_concurrency(), lit);
  EXPECT_GT(lit, 50.0);
  EXPECT_LT(lit, 99.0);
}

}  // namespace
}  // namespace sl
