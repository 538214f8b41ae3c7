// The irregular z-buffer against the ray-traced reference (llvmpipe, 160x90): exact up to a
// handful of tie pixels on the builtin scenes, Sponza's alpha-masked casters and a masked quad;
// the overflow path on purpose; composition with pixel-correct; layouts of several views, and
// those it cannot use.
#include "irregular/izb_state.h"
#include "metrics/metrics.h"
#include "scene/shapes.h"
#include "tests/gl_test_util.h"
#include "technique.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdlib>
#include <fstream>
#include <string>
#include <tuple>

namespace sl {
namespace {

constexpr int kIrregularW = 160, kIrregularH = 90;

struct Result {
  ErrorMetrics error;
  long long wrong = 0, covered = 0, shadowed = 0, nonfinite = 0;
};

Result compareWithReference(const Scene& scene, const test::Frame& f, double time = 0.0) {
  ReferenceTracer tracer(scene, time);
  ReferenceOptions options;
  options.time = time;
  const std::vector<float> ref = tracer.visibility(f.gbuffer(), options);
  const size_t n = static_cast<size_t>(f.width) * f.height;
  std::vector<float> vis(n);
  std::vector<uint8_t> valid(n);
  Result r;
  for (size_t i = 0; i < n; ++i) {
    vis[i] = f.visibility[2 * i];
    valid[i] = f.position[4 * i + 3] > 0.5f;
    r.covered += valid[i];
    r.shadowed += valid[i] && ref[i] < 0.5f;
    r.wrong += valid[i] && !(std::abs(vis[i] - ref[i]) <= kWrongThreshold);
  }
  r.error = compareVisibility(vis.data(), ref.data(), valid.data(), n);
  r.nonfinite = f.nonfinite();
  return r;
}

// One frame of `preset` on `scene` from `cam`, with the viewport kept for its state.
test::Frame renderWith(test::GlHarness& h, const Scene& scene, Viewport& vp, const Camera& cam, int frames = 1,
                       double time = 0.0) {
  h.renderer.setScene(scene);
  FrameInput in;
  in.camera = cam;
  in.time = time;
  in.width = kIrregularW;
  in.height = kIrregularH;
  for (int i = 0; i < frames; ++i) h.renderer.render(in, {&vp});
  EXPECT_TRUE(h.shaders.errors().empty()) << (h.shaders.errors().empty() ? "" : h.shaders.errors().front());
  return test::readFrame(h.renderer, vp, kIrregularW, kIrregularH);
}

std::string sharedDir() {
  const char* env = std::getenv("SHADOWLAB_SHARED");
  return env && *env ? env : std::string(SHADOWLAB_SOURCE_DIR) + "/../shared";
}

TEST(Irregular, MatchesTheReferenceOnBuiltinScenes) {
  test::GlHarness h;
  for (const char* id : {"basic", "columns", "thin-casters", "terrain", "spotlight"}) {
    const Scene scene = loadScene(id, defaultAssetsDir());
    Viewport vp(makeTechnique("alias-free"));
    const Result r = compareWithReference(scene, renderWith(h, scene, vp, scene.cameras.front()));
    std::printf("%-14s alias-free: %lld wrong of %lld covered (%lld shadowed)\n", id, r.wrong, r.covered, r.shadowed);
    EXPECT_EQ(r.nonfinite, 0) << id;
    EXPECT_GT(r.shadowed, 50) << id << ": a scene without shadows would pass anything";
    EXPECT_LE(r.wrong, 3) << id;  // numerical ties only
    auto* state = dynamic_cast<IzbState*>(vp.representation.get());
    ASSERT_NE(state, nullptr);
    EXPECT_EQ(state->overflowCount(), 0u) << id;
    EXPECT_GT(state->listedCount(), 0u) << id;
  }
  EXPECT_EQ(glDebugErrorCount(), 0);
}

// Moving casters: the triangles follow the frame's time (rebuilt when it changes).
TEST(Irregular, MovingCastersAreTestedWhereTheyAreAtTheFrameTime) {
  test::GlHarness h;
  const Scene scene = loadScene("moving", defaultAssetsDir());
  Viewport vp(makeTechnique("alias-free"));
  std::vector<float> first;
  for (double time : {0.0, 1.3, 2.9}) {
    const test::Frame f = renderWith(h, scene, vp, scene.cameras.front(), 1, time);
    const Result r = compareWithReference(scene, f, time);
    EXPECT_LE(r.wrong, 3) << "time " << time;
    EXPECT_GT(r.shadowed, 5) << "time " << time;
    if (first.empty()) {
      first = f.visibility;
      continue;
    }
    // The shadows moved with their casters (a stale triangle buffer would keep time 0's).
    long long changed = 0;
    for (size_t i = 0; i < first.size(); i += 2) changed += std::abs(first[i] - f.visibility[i]) > 0.5f;
    EXPECT_GT(changed, 5) << "time " << time;
  }
}

// The same frames with the standard map are far from exact: the comparison can fail.
TEST(Irregular, StandardMapIsNotExactOnThinCasters) {
  test::GlHarness h;
  const Scene scene = loadScene("thin-casters", defaultAssetsDir());
  Viewport vp(makeTechnique("standard", {"shadowmap.size=256"}));
  const Result r = compareWithReference(scene, renderWith(h, scene, vp, scene.cameras.front()));
  EXPECT_GT(r.wrong, 10);
}

// A checkerboard of holes (alpha 0 / 255) in a quad over a ground: light passes the holes.
Scene maskedQuadScene() {
  Scene scene;
  scene.name = "masked-quad";
  Material ground;
  scene.materials.push_back(ground);
  Material mask;
  mask.baseColorTexture = 0;
  mask.alphaMask = true;
  mask.doubleSided = true;
  scene.materials.push_back(mask);
  Texture tex;
  tex.name = "checker";
  tex.width = tex.height = 8;
  tex.rgba.assign(8 * 8 * 4, 255);
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x)
      if ((x + y) % 2) tex.rgba[4 * (y * 8 + x) + 3] = 0;
  scene.textures.push_back(tex);
  scene.meshes.push_back(makePlane(8.0f, 8.0f, 8));
  scene.meshes.push_back(makePlane(2.0f, 2.0f, 1));
  scene.meshes[1].material = 1;
  scene.instances.push_back({"ground", 0, glm::mat4(1.0f), {}});
  scene.instances.push_back({"mask", 1, glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 0)), {}});
  scene.light.direction = glm::normalize(glm::vec3(0.2f, -1.0f, 0.1f));
  Camera cam;
  cam.position = {0.5f, 5.0f, 3.0f};
  cam.target = {0.0f, 0.0f, 0.0f};
  scene.cameras.push_back(cam);
  return scene;
}

TEST(Irregular, AlphaMaskedCastersLetLightThroughTheirHoles) {
  test::GlHarness h;
  const Scene scene = maskedQuadScene();
  Viewport vp(makeTechnique("alias-free"));
  const test::Frame f = renderWith(h, scene, vp, scene.cameras.front());
  const Result r = compareWithReference(scene, f);
  EXPECT_LE(r.wrong, 3);
  EXPECT_GT(r.shadowed, 200);
  // Not all opaque: the quad's shadow on the ground has lit holes (about half of its area).
  long long lit = 0;
  for (size_t i = 0; i < f.visibility.size() / 2; ++i)
    lit += f.position[4 * i + 3] > 0.5f && f.visibility[2 * i] > 0.5f;
  EXPECT_GT(lit, r.covered - r.shadowed - 10);
}

TEST(Irregular, SponzaWithAlphaMaskedCastersMatchesTheReference) {
  if (!std::ifstream(sharedDir() + "/scenes-real/sponza/Sponza.gltf"))
    GTEST_SKIP() << "shared/scenes-real not found under " << sharedDir() << ": Sponza is not compared";
  test::GlHarness h;
  Scene scene = loadScene("sponza", defaultAssetsDir());
  // Sun on the floor under the plants and chains (the default camera's floor is in shadow).
  scene.light.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.15f));
  Camera cam = scene.cameras.front();
  cam.position = {-9.0f, 7.0f, 0.3f};
  cam.target = {4.0f, 0.5f, 2.5f};
  Viewport vp(makeTechnique("alias-free"));
  const Result r = compareWithReference(scene, renderWith(h, scene, vp, cam));
  std::printf("sponza alias-free: %lld wrong of %lld covered (%lld shadowed)\n", r.wrong, r.covered, r.shadowed);
  EXPECT_LE(r.wrong, 3);
  EXPECT_GT(r.covered - r.shadowed, 500);  // the lit floor
  EXPECT_GT(r.shadowed, 500);
}

// A list buffer of one entry: every other sample overflows, is counted, and takes the map test.
TEST(Irregular, OverflowIsCountedAndFallsBackToTheMap) {
  test::GlHarness h;
  const Scene scene = loadScene("basic", defaultAssetsDir());
  Viewport vp(makeTechnique("alias-free", {"izb.capacity=0.01", "shadowmap.size=2048"}));
  const test::Frame f = renderWith(h, scene, vp, scene.cameras.front());
  auto* state = dynamic_cast<IzbState*>(vp.representation.get());
  ASSERT_NE(state, nullptr);
  const uint32_t listed = state->listedCount();
  EXPECT_GT(listed, 1000u);
  EXPECT_EQ(state->overflowCount(), listed - 1);  // capacity max(1, 14400 * 0.01 %) = 1
  EXPECT_NE(state->status().find("overflowed"), std::string::npos) << state->status();
  const Result r = compareWithReference(scene, f);
  EXPECT_EQ(r.nonfinite, 0);
  // The fallback is the shadow-map test: close to the truth, not garbage.
  EXPECT_LT(r.error.wrongPixelPct, 2.0);
  // Raising the capacity again recovers the exact result.
  vp.technique.params.setAssignment("izb.capacity=100");
  const Result exact = compareWithReference(scene, renderWith(h, scene, vp, scene.cameras.front()));
  EXPECT_EQ(state->overflowCount(), 0u);
  EXPECT_LE(exact.wrong, 3);
}

// The grid decides only where samples are listed, never an answer: its smallest, the default
// and its largest give the same bits. At 4096² cells a scan of one invocation per 256 cells
// asked for 65536 work groups, one more than GL guarantees, and left the offsets unset.
TEST(Irregular, EveryGridSizeGivesTheSameAnswerUpToTheLargest) {
  test::GlHarness h;
  const Scene scene = loadScene("basic", defaultAssetsDir());
  std::vector<float> atDefault;
  for (const char* grid : {"izb.grid=512", "izb.grid=16", "izb.grid=4096"}) {
    Viewport vp(makeTechnique("alias-free", {grid}));
    const test::Frame f = renderWith(h, scene, vp, scene.cameras.front());
    EXPECT_EQ(glDebugErrorCount(), 0) << grid;
    const Result r = compareWithReference(scene, f);
    EXPECT_LE(r.wrong, 3) << grid;
    EXPECT_GT(r.shadowed, 50) << grid;
    if (atDefault.empty()) atDefault = f.visibility;
    long long differ = 0;
    for (size_t i = 0; i < atDefault.size(); i += 2) differ += atDefault[i] != f.visibility[i];
    EXPECT_EQ(differ, 0) << grid;
  }
}

TEST(Irregular, ComposesWithPixelCorrectAccumulation) {
  test::GlHarness h;
  const Scene scene = loadScene("columns", defaultAssetsDir());
  Viewport vp(makeTechnique("alias-free-pixel-correct"));
  const Result r = compareWithReference(scene, renderWith(h, scene, vp, scene.cameras.front(), 3));
  EXPECT_EQ(r.nonfinite, 0);
  EXPECT_LE(r.wrong, 3);
  EXPECT_GT(r.shadowed, 50);
}

// The accumulation's confidence (Scherzer et al., eq. 5) is the representation's: 1 where a
// listed sample's bit answered (exact at the pixel), the map's texel-centre distance only where
// a sample fell back to the map (here every sample past a capacity of one).
TEST(Irregular, ConfidenceIsOneWhereTheBitsAnswerAndTheMapsWhereItFellBack) {
  test::GlHarness h;
  const Scene scene = loadScene("basic", defaultAssetsDir());
  for (const char* capacity : {"izb.capacity=100", "izb.capacity=0.01"}) {
    Viewport vp(makeTechnique("alias-free-pixel-correct", {capacity}));
    const test::Frame f = renderWith(h, scene, vp, scene.cameras.front());
    const std::vector<float> raw = vp.rawVisibilityTexture()->readFloats(2);
    long long covered = 0, sure = 0;
    for (size_t i = 0; i < raw.size() / 2; ++i) {
      if (!(f.position[4 * i + 3] > 0.5f)) continue;
      ++covered;
      sure += raw[2 * i + 1] == 1.0f;
    }
    ASSERT_GT(covered, kIrregularW * kIrregularH / 2) << capacity;
    if (std::string(capacity) == "izb.capacity=100")
      EXPECT_EQ(sure, covered) << capacity;
    else
      EXPECT_LT(sure, covered * 9 / 10) << capacity;  // the map's confidence: 1 only on a centre
  }
}

// Several views are listed one after another, a sample in every view whose window holds it: the
// cascades under the sun and a point light's cube and tetrahedron faces are exact as one view is.
Result severalViews(test::GlHarness& h, const std::string& sceneId, const std::string& layout) {
  const Scene scene = loadScene(sceneId, defaultAssetsDir());
  Viewport vp(makeTechnique("alias-free", {"technique.layout=" + layout, "shadowmap.size=512"}));
  const Result r = compareWithReference(scene, renderWith(h, scene, vp, scene.cameras.front()));
  std::printf("%s alias-free over %s: %lld wrong of %lld covered (%lld shadowed); %s\n", sceneId.c_str(),
              layout.c_str(), r.wrong, r.covered, r.shadowed, vp.representation->status().c_str());
  EXPECT_NE(vp.representation->status().find("listings of samples in"), std::string::npos)
      << vp.representation->status();
  EXPECT_EQ(r.nonfinite, 0) << layout;
  EXPECT_GT(r.shadowed, 50) << layout;
  return r;
}

TEST(Irregular, CascadesAreListedViewByViewAndMatchTheReference) {
  test::GlHarness h;
  EXPECT_LE(severalViews(h, "basic", "cascaded").wrong, 3);
}

// A point light's views on street's lamp: the cube's and the tetrahedron's faces, each in a
// layer, Liao's packing (the four faces share one layer, each in its triangle) and the cube's
// atlas (each face in its square of one layer). The lists are built view by view, so sharing a
// layer changes nothing of the exact test.
class IrregularPointLayoutGl : public ::testing::TestWithParam<std::string> {};

TEST_P(IrregularPointLayoutGl, FacesAreListedViewByViewAndMatchTheReference) {
  test::GlHarness h;
  EXPECT_LE(severalViews(h, "street", GetParam()).wrong, 3);
}

INSTANTIATE_TEST_SUITE_P(PointLayouts, IrregularPointLayoutGl,
                         ::testing::Values("cube", "tetrahedron", "tetrahedron-packed", "cube-atlas"),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

// Views no matrix places points in get a clear status and the map test everywhere: the log warp
// under a sun (LogPSM) and the paraboloids.
TEST(Irregular, LogWarpedAndParaboloidViewsGiveAStatusAndTheMapTest) {
  test::GlHarness h;
  for (const auto& [sceneId, layout, word] :
       {std::tuple<const char*, const char*, const char*>{"basic", "logpsm", "warped"},
        {"street", "dual-paraboloid", "paraboloid"}}) {
    const Scene scene = loadScene(sceneId, defaultAssetsDir());
    Viewport vp(makeTechnique("alias-free", {std::string("technique.layout=") + layout}));
    const test::Frame f = renderWith(h, scene, vp, scene.cameras.front());
    const std::string status = vp.representation->status();
    EXPECT_NE(status.find(std::string(word) + " view(s): every pixel uses the shadow-map test"), std::string::npos)
        << layout << ": " << status;
    const Result r = compareWithReference(scene, f);
    EXPECT_EQ(r.nonfinite, 0) << layout;
    EXPECT_LT(r.error.wrongPixelPct, 5.0) << layout << ": the map's test, not garbage";
  }
}

// A beam from behind the camera to far ahead under a sun from behind: under a light-space warp
// (LiSPSM, TSM) its long faces cross the warp's centre of projection, where the projection of
// its corners wraps around; the grid takes the part of it within the listed samples' clip w
// (izb_triangles.comp, clippedBounds), and its shadow on the ground ahead is exact.
Scene beamScene() {
  Scene scene;
  scene.name = "beam";
  scene.materials.push_back(Material{});
  scene.meshes.push_back(makePlane(80.0f, 80.0f, 8));
  scene.meshes.push_back(makeBox({0.4f, 0.4f, 40.0f}));
  scene.instances.push_back({"ground", 0, glm::mat4(1.0f), {}});
  scene.instances.push_back({"beam", 1, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 2.5f, 0.0f)), {}});
  scene.light.direction = glm::normalize(glm::vec3(-0.6f, -1.0f, -0.5f));
  Camera cam;
  cam.position = {0.5f, 1.7f, 12.0f};
  cam.target = {0.0f, 0.5f, -10.0f};
  scene.cameras.push_back(cam);
  return scene;
}

TEST(Irregular, WarpedGridsAcrossTheLightMatchTheReferenceWithCastersBehindTheirCentre) {
  test::GlHarness h;
  const Scene scene = beamScene();
  for (const char* layout : {"lispsm", "tsm"}) {
    Viewport vp(makeTechnique("alias-free", {std::string("technique.layout=") + layout}));
    const Result r = compareWithReference(scene, renderWith(h, scene, vp, scene.cameras.front()));
    const std::string status = vp.representation->status();
    EXPECT_NE(status.find("samples in"), std::string::npos) << layout << ": " << status;
    EXPECT_EQ(r.nonfinite, 0) << layout;
    EXPECT_GT(r.shadowed, 200) << layout << ": the beam's shadow on the ground";
    EXPECT_LE(r.wrong, 3) << layout;
  }
}

TEST(Irregular, ListViewShowsTheGrid) {
  test::GlHarness h;
  const Scene scene = loadScene("basic", defaultAssetsDir());
  Viewport vp(makeTechnique("alias-free", {"izb.grid=64"}));
  vp.shownViews = {"izb-lists"};
  renderWith(h, scene, vp, scene.cameras.front());
  const Texture2D* view = vp.viewTexture("izb-lists");
  ASSERT_NE(view, nullptr);
  const std::vector<float> rgba = view->readFloats(4);
  long long empty = 0, listed = 0;
  for (size_t i = 0; i < rgba.size(); i += 4) (rgba[i] + rgba[i + 1] + rgba[i + 2] == 0.0f ? empty : listed)++;
  EXPECT_GT(empty, 0);   // cells no visible sample falls in
  EXPECT_GT(listed, 0);  // and cells with lists
}

}  // namespace
}  // namespace sl
