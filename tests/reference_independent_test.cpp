// The Embree reference against an independently written ray caster (double precision, a 2D
// grid of triangles projected along the light, no Embree) on the builtin scenes at 160x90.
// Pixels where the caster's own answer changes when the point moves by a few float units, or
// the height tolerance doubles or halves, are ties and not counted: everywhere else the two must
// agree exactly.
#include "gl_test_util.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace sl {
namespace {

struct WorldTriangle {
  glm::dvec3 a, b, c;
};

// Directional light only: every shadow ray is parallel to `towardLight`, so a ray is a point in
// the plane perpendicular to it and only the triangles whose projection covers that point can
// block it.
class GridCaster {
 public:
  GridCaster(const Scene& scene, glm::dvec3 towardLight) : l_(glm::normalize(towardLight)) {
    const glm::dvec3 helper = std::abs(l_.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    u_ = glm::normalize(glm::cross(helper, l_));
    v_ = glm::cross(l_, u_);
    for (const Instance& inst : scene.instances) {
      const Mesh& mesh = scene.meshes[static_cast<size_t>(inst.mesh)];
      const glm::mat4 m = inst.transformAt(0.0);
      std::vector<WorldTriangle> tris;
      auto world = [&](uint32_t i) { return glm::dvec3(glm::vec3(m * glm::vec4(mesh.positions[i], 1.0f))); };
      for (size_t k = 0; k + 2 < mesh.indices.size(); k += 3)
        tris.push_back({world(mesh.indices[k]), world(mesh.indices[k + 1]), world(mesh.indices[k + 2])});
      instances_.push_back(tris);
      for (const WorldTriangle& t : tris)
        for (const glm::dvec3& p : {t.a, t.b, t.c}) {
          lo_ = glm::min(lo_, project(p));
          hi_ = glm::max(hi_, project(p));
        }
    }
    cell_ = std::max((hi_.x - lo_.x), (hi_.y - lo_.y)) / kCells;
    cells_.resize(kCells * kCells);
    for (size_t i = 0; i < instances_.size(); ++i)
      for (size_t k = 0; k < instances_[i].size(); ++k) bin(i, k);
  }

  const WorldTriangle* triangle(int instance, int index) const {
    if (instance < 0 || static_cast<size_t>(instance) >= instances_.size()) return nullptr;
    if (index < 0 || static_cast<size_t>(index) >= instances_[instance].size()) return nullptr;
    return &instances_[instance][index];
  }

  // True when something lies on the ray from p toward the light higher than `minHeight` above
  // the receiver's plane (normal n).
  bool blocked(const glm::dvec3& p, const glm::dvec3& n, double minHeight) const {
    const glm::dvec2 q = project(p);
    const int cx = static_cast<int>((q.x - lo_.x) / cell_), cy = static_cast<int>((q.y - lo_.y) / cell_);
    if (cx < 0 || cy < 0 || cx >= kCells || cy >= kCells) return false;
    const double cosine = glm::dot(n, l_);
    for (const auto& [i, k] : cells_[static_cast<size_t>(cy) * kCells + cx]) {
      const double t = hit(instances_[i][k], p);
      if (t > 0.0 && t * cosine > minHeight) return true;
    }
    return false;
  }

 private:
  static constexpr int kCells = 256;
  glm::dvec2 project(const glm::dvec3& p) const { return {glm::dot(p, u_), glm::dot(p, v_)}; }

  void bin(size_t i, size_t k) {
    const WorldTriangle& t = instances_[i][k];
    glm::dvec2 a = project(t.a), b = project(t.b), c = project(t.c);
    glm::dvec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    const int x0 = std::max(0, static_cast<int>((lo.x - lo_.x) / cell_) - 1);
    const int y0 = std::max(0, static_cast<int>((lo.y - lo_.y) / cell_) - 1);
    const int x1 = std::min(kCells - 1, static_cast<int>((hi.x - lo_.x) / cell_) + 1);
    const int y1 = std::min(kCells - 1, static_cast<int>((hi.y - lo_.y) / cell_) + 1);
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) cells_[static_cast<size_t>(y) * kCells + x].push_back({i, k});
  }

  // Distance along the light direction from p to triangle t, or -1 when the ray misses it
  // (Moller-Trumbore, in double).
  double hit(const WorldTriangle& t, const glm::dvec3& p) const {
    const glm::dvec3 e1 = t.b - t.a, e2 = t.c - t.a;
    const glm::dvec3 h = glm::cross(l_, e2);
    const double det = glm::dot(e1, h);
    if (std::abs(det) < 1e-300) return -1.0;
    const glm::dvec3 s = p - t.a;
    const double bu = glm::dot(s, h) / det;
    if (bu < 0.0 || bu > 1.0) return -1.0;
    const glm::dvec3 qv = glm::cross(s, e1);
    const double bv = glm::dot(l_, qv) / det;
    if (bv < 0.0 || bu + bv > 1.0) return -1.0;
    return glm::dot(e2, qv) / det;
  }

  glm::dvec3 l_, u_, v_;
  glm::dvec2 lo_{1e300}, hi_{-1e300};
  double cell_ = 1.0;
  std::vector<std::vector<WorldTriangle>> instances_;
  std::vector<std::vector<std::pair<size_t, size_t>>> cells_;
};

struct Agreement {
  long long covered = 0, ties = 0, disagree = 0, terminator = 0, shadowed = 0;
  long long terminatorLitByTechnique = 0;  // the technique's facet test disagrees with the exact one
};

// The caster's verdict for one pixel: 1 lit, 0 shadowed, -1 a tie.
int independentVisibility(const GridCaster& caster, const glm::dvec3& p, const glm::dvec3& shading,
                          const WorldTriangle* tri, const glm::dvec3& toLight, bool& terminator) {
  terminator = false;
  if (glm::dot(shading, toLight) <= 0.0) return 0;
  glm::dvec3 n = shading, q = p;
  if (tri) {
    n = glm::normalize(glm::cross(tri->b - tri->a, tri->c - tri->a));
    if (glm::dot(n, shading) < 0.0) n = -n;
    q = p - n * glm::dot(n, p - tri->a);
  }
  if (glm::dot(n, toLight) <= 0.0) {
    terminator = true;
    return 0;
  }
  const double scale = std::max({std::abs(q.x), std::abs(q.y), std::abs(q.z), 1e-3});
  const double height = scale / 1048576.0, step = scale / 262144.0;
  const glm::dvec3 t1 = glm::normalize(glm::cross(n, std::abs(n.x) < 0.9 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0)));
  const glm::dvec3 t2 = glm::cross(n, t1);
  const bool centre = caster.blocked(q, n, height);
  const std::array<glm::dvec3, 4> moves = {t1, -t1, t2, -t2};
  for (const glm::dvec3& m : moves)
    if (caster.blocked(q + m * step, n, height) != centre) return -1;
  if (caster.blocked(q, n, 0.5 * height) != centre || caster.blocked(q, n, 2.0 * height) != centre) return -1;
  return centre ? 0 : 1;
}

Agreement compareOnScene(const std::string& id) {
  test::GlHarness h;
  Scene scene = loadScene(id, defaultAssetsDir());
  const test::Frame f = test::renderOnce(h, scene, "standard", {}, 160, 90);
  const std::vector<float> embree = ReferenceTracer(scene).visibility(f.gbuffer(), ReferenceOptions{});
  const glm::dvec3 toLight = -glm::dvec3(glm::normalize(scene.light.direction));
  GridCaster caster(scene, toLight);

  Agreement a;
  for (size_t i = 0; i < embree.size(); ++i) {
    if (f.position[4 * i + 3] < 0.5f) continue;
    ++a.covered;
    const glm::dvec3 p(f.position[4 * i], f.position[4 * i + 1], f.position[4 * i + 2]);
    const glm::dvec3 n(f.normal[4 * i], f.normal[4 * i + 1], f.normal[4 * i + 2]);
    const WorldTriangle* tri = f.surface[4 * i] > 0 ? caster.triangle(static_cast<int>(f.surface[4 * i]) - 1,
                                                                      static_cast<int>(f.surface[4 * i + 1]))
                                                    : nullptr;
    EXPECT_NE(tri, nullptr) << "covered pixel " << i << " names no triangle";
    bool terminator = false;
    const int verdict = independentVisibility(caster, p, glm::normalize(n), tri, toLight, terminator);
    a.terminator += terminator ? 1 : 0;
    a.terminatorLitByTechnique += terminator && f.visibility[2 * i] > 0.5f ? 1 : 0;
    if (verdict < 0) {
      ++a.ties;
      continue;
    }
    a.shadowed += verdict == 0 ? 1 : 0;
    if ((embree[i] > 0.5f) != (verdict == 1)) ++a.disagree;
  }
  std::printf(
      "%s: %lld covered, %lld shadowed, %lld ties, %lld terminator pixels (%lld lit by standard), %lld disagree\n",
      id.c_str(), a.covered, a.shadowed, a.ties, a.terminator, a.terminatorLitByTechnique, a.disagree);
  return a;
}

class ReferenceIndependent : public ::testing::TestWithParam<std::string> {};

TEST_P(ReferenceIndependent, AgreesWithAGridCasterInDoubleExceptAtTies) {
  const Agreement a = compareOnScene(GetParam());
  EXPECT_GT(a.covered, 5000);
  EXPECT_GT(a.shadowed, 50);
  EXPECT_EQ(a.disagree, 0);
  EXPECT_LT(a.ties, a.covered / 100);  // ties are the shadows' edges at float precision, no more
  // Techniques apply the same terminator rule (from the facet normal of screen derivatives).
  EXPECT_EQ(a.terminatorLitByTechnique, 0);
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Opaque builtin scenes with a directional light (alpha-masked casters are Embree's filter).
INSTANTIATE_TEST_SUITE_P(Builtin, ReferenceIndependent,
                         ::testing::Values("basic", "columns", "terrain", "dueling-frusta", "thin-casters"),
                         [](const auto& info) {
                           std::string name = info.param;
                           std::replace(name.begin(), name.end(), '-', '_');
                           return name;
                         });

// The real CAD engine (millimetres, 2 m ground, thin parts): opaque, so the caster applies.
TEST(ReferenceIndependentReal, EngineAgreesWithTheGridCaster) {
  const char* env = std::getenv("SHADOWLAB_SHARED");
  const std::string shared = env && *env ? env : std::string(SHADOWLAB_SOURCE_DIR) + "/../shared";
  if (!std::ifstream(shared + "/scenes-real/2cylinderengine/2CylinderEngine.gltf"))
    GTEST_SKIP() << "shared/scenes-real not found under " << shared << ": the engine is not compared";
  const Agreement a = compareOnScene("engine");
  EXPECT_GT(a.shadowed, 50);
  EXPECT_EQ(a.disagree, 0);
  EXPECT_LT(a.ties, a.covered / 100);
}

}  // namespace
}  // namespace sl
