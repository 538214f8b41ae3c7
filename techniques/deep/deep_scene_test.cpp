// The scene side of deep shadow maps: hair and volume validation, scene effects, the density
// function and the reference's transmittance on cases computed by hand.
#include "tests/assets_dir.h"
#include "reference/reference.h"
#include "scene/scene.h"
#include "scene/scene_effects.h"
#include "scene/volume_density.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

namespace sl {
namespace {

namespace fs = std::filesystem;
using test::kAssets;

std::string writeScene(const std::string& name, const std::string& text) {
  const fs::path dir = fs::temp_directory_path() / ("shadowlab_deep_test_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const fs::path p = dir / name;
  std::ofstream(p, std::ios::binary) << text;
  return p.string();
}

std::string loadError(const std::string& path) {
  try {
    loadScene(path, kAssets);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

const std::string kObjects =
    R"("objects":[{"name":"ground","shape":"plane","size":[4,4]},{"name":"ball","shape":"sphere","radius":0.5,"transform":{"translate":[0,1,0]}}])";

std::string hairScene(const std::string& hair) { return "{" + kObjects + R"(,"hair":[)" + hair + "]}"; }
std::string volumeScene(const std::string& volume) { return "{" + kObjects + R"(,"volumes":[)" + volume + "]}"; }

TEST(DeepScene, BadHairValuesNameTheFileAndField) {
  struct Case {
    std::string hair, expect;
  } cases[] = {
      {R"({"on":"ball","count":-1})", "hair[0].count"},
      {R"({"on":"ball","opacity":1.5})", "hair[0].opacity"},
      {R"({"on":"ball","opacity":-0.1})", "hair[0].opacity"},
      {R"({"on":"nothing"})", "no object named 'nothing'"},
      {R"({"count":10})", "missing 'on'"},
      {R"({"on":"ball","width":0})", "hair[0].width"},
      {R"({"on":"ball","length":-2})", "hair[0].length"},
      {R"({"on":"ball","lenght":2})", "lenght"},
  };
  for (const Case& c : cases) {
    const std::string path = writeScene("bad_hair.json", hairScene(c.hair));
    const std::string err = loadError(path);
    EXPECT_NE(err.find(path), std::string::npos) << c.hair << " -> " << err;
    EXPECT_NE(err.find(c.expect), std::string::npos) << c.hair << " -> " << err;
  }
}

TEST(DeepScene, BadVolumeValuesNameTheFileAndField) {
  struct Case {
    std::string volume, expect;
  } cases[] = {
      {R"({"shape":"box","size":[1,1,1],"extinction":-1})", "volumes[0].extinction"},
      {R"({"shape":"box","extinction":1})", "missing 'size'"},
      {R"({"shape":"cone","extinction":1})", "unknown volume shape 'cone'"},
      {R"({"shape":"sphere","radius":1,"extinction":1,"noise":2})", "volumes[0].noise"},
      {R"({"shape":"sphere","radius":0,"extinction":1})", "volumes[0].radius"},
      {R"({"shape":"sphere","radius":1})", "missing 'extinction'"},
  };
  for (const Case& c : cases) {
    const std::string path = writeScene("bad_volume.json", volumeScene(c.volume));
    const std::string err = loadError(path);
    EXPECT_NE(err.find(path), std::string::npos) << c.volume << " -> " << err;
    EXPECT_NE(err.find(c.expect), std::string::npos) << c.volume << " -> " << err;
  }
  const std::string opacity =
      writeScene("bad_opacity.json", R"({"objects":[{"name":"ground","shape":"plane","size":[4,4],"opacity":3}]})");
  EXPECT_NE(loadError(opacity).find("objects[0].opacity"), std::string::npos) << loadError(opacity);
}

TEST(DeepScene, EffectsFollowTheCasters) {
  EXPECT_FALSE(sceneEffects(loadScene("basic", kAssets)).semiTransparent);
  EXPECT_TRUE(sceneEffects(loadScene("hair", kAssets)).semiTransparent);
  EXPECT_TRUE(sceneEffects(loadScene("smoke", kAssets)).semiTransparent);
  // Zero strands: no geometry, nothing semi-transparent.
  const Scene none = loadScene(writeScene("no_hair.json", hairScene(R"({"on":"ball","count":0})")), kAssets);
  EXPECT_FALSE(sceneEffects(none).semiTransparent);
  EXPECT_EQ(none.instances.size(), 2u);
}

TEST(DeepScene, HairIsDeterministicAndOnTheObject) {
  const std::string path = writeScene("hair.json", hairScene(R"({"on":"ball","count":50,"length":0.2,"seed":4})"));
  const Scene a = loadScene(path, kAssets), b = loadScene(path, kAssets);
  ASSERT_EQ(a.meshes.size(), 3u);
  EXPECT_EQ(a.meshes[2].positions, b.meshes[2].positions);
  EXPECT_EQ(a.meshes[2].indices.size(), 50u * 6u * 6u);  // 6 quads of 2 triangles per strand
  EXPECT_TRUE(a.materials[a.meshes[2].material].alphaBlend);
  // Roots lie on the sphere (radius 0.5 around (0,1,0)), tips at most length + width further.
  for (size_t i = 0; i < a.meshes[2].positions.size(); ++i) {
    const float r = glm::length(a.meshes[2].positions[i] - glm::vec3(0, 1, 0));
    EXPECT_GE(r, 0.45f);
    EXPECT_LE(r, 0.5f + 0.2f + 0.01f);
  }
}

TEST(DeepScene, DensityIsBoundedAndZeroOutside) {
  Volume v;
  v.shape = Volume::Shape::Sphere;
  v.halfSize = glm::vec3(1.0f);
  v.extinction = 4.0f;
  v.noise = 1.0f;
  v.noiseScale = 3.0f;
  float lo = 1e9f, hi = -1e9f;
  for (int i = 0; i < 2000; ++i) {
    const glm::vec3 p(std::sin(i * 1.3f) * 0.9f, std::cos(i * 0.7f) * 0.5f, std::sin(i * 2.1f) * 0.4f);
    const float s = volumeExtinction(v, p);
    ASSERT_TRUE(std::isfinite(s));
    lo = std::min(lo, s);
    hi = std::max(hi, s);
  }
  EXPECT_GE(lo, 0.0f);
  EXPECT_LE(hi, 4.0f);
  EXPECT_GT(hi - lo, 1.0f);  // the noise modulates it
  EXPECT_EQ(volumeExtinction(v, glm::vec3(1.5f, 0, 0)), 0.0f);
}

// Reference light fraction of the ground point under the casters, light straight down.
float referenceAt(const std::string& json, const glm::vec3& p) {
  const Scene s = loadScene(writeScene("ref.json", json), kAssets);
  ReferenceTracer tracer(s);
  const float position[4] = {p.x, p.y, p.z, 1}, normal[4] = {0, 1, 0, 0};
  const GBufferView g{1, 1, position, normal, nullptr};
  return tracer.visibility(g, ReferenceOptions{}).at(0);
}

const std::string kDown = R"("light":{"type":"directional","direction":[0,-1,0]})";

TEST(DeepScene, ReferenceTransmittanceByHand) {
  // Constant-density box, 0.5 thick, sigma 2: T = exp(-1).
  const std::string box = R"({"objects":[{"name":"ground","shape":"plane","size":[4,4]}],)"
                          R"("volumes":[{"shape":"box","center":[0,1,0],"size":[1,0.5,1],"extinction":2}],)" +
                          kDown + "}";
  EXPECT_NEAR(referenceAt(box, glm::vec3(0.13f, 0, 0.07f)), std::exp(-1.0f), 1e-4f);
  EXPECT_NEAR(referenceAt(box, glm::vec3(1.5f, 0, 0)), 1.0f, 1e-6f);  // beside it
  // Three sheets of opacity 0.4: T = 0.6^3.
  std::string sheets = R"({"objects":[{"name":"ground","shape":"plane","size":[4,4]})";
  for (int k = 1; k <= 3; ++k)
    sheets += R"(,{"shape":"plane","size":[1,1],"opacity":0.4,"transform":{"translate":[0,)" + std::to_string(k * 0.3) +
              ",0]}}";
  sheets += "]," + kDown + "}";
  EXPECT_NEAR(referenceAt(sheets, glm::vec3(0.13f, 0, 0.07f)), 0.216f, 1e-5f);
  // Opacity 0 lets everything through, opacity 1 nothing; density 0 and very high.
  const auto one = [&](const std::string& object) {
    return R"({"objects":[{"name":"ground","shape":"plane","size":[4,4]},)" + object + "]," + kDown + "}";
  };
  EXPECT_NEAR(referenceAt(one(R"({"shape":"plane","size":[1,1],"opacity":0,"transform":{"translate":[0,1,0]}})"),
                          glm::vec3(0.13f, 0, 0.07f)),
              1.0f, 1e-6f);
  EXPECT_EQ(referenceAt(one(R"({"shape":"plane","size":[1,1],"opacity":1,"transform":{"translate":[0,1,0]}})"),
                        glm::vec3(0.13f, 0, 0.07f)),
            0.0f);
  const auto dense = [&](const char* sigma) {
    return R"({"objects":[{"name":"ground","shape":"plane","size":[4,4]}],"volumes":[{"shape":"sphere","center":[0,1,0],"radius":0.5,"extinction":)" +
           std::string(sigma) + "}]," + kDown + "}";
  };
  EXPECT_EQ(referenceAt(dense("0"), glm::vec3(0, 0, 0)), 1.0f);
  const float high = referenceAt(dense("1000000"), glm::vec3(0, 0, 0));
  EXPECT_TRUE(std::isfinite(high));
  EXPECT_GE(high, 0.0f);
  EXPECT_LT(high, 1e-6f);
}

}  // namespace
}  // namespace sl
