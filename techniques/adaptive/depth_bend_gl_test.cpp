// The kept bend of the tiled maps' depth-discontinuity term (depth_bend.h) against values worked
// by hand: a plane has none, a step of 0.25 bends by 0.25 on both of its sides, a parabola by its
// second difference; a tile is recomputed when it is marked drawn and only then.
#include "adaptive/depth_bend.h"
#include "tests/gl_test_util.h"

namespace sl {
namespace {

constexpr int kPage = 32, kPoolSide = 2, kSide = kPage * kPoolSide;
const std::string kDefines = "#define SL_VIRTUAL_PAGE 32\n#define SL_VIRTUAL_POOL_SIDE 2\n";

using DepthFn = float (*)(int x, int y);  // local texel of a tile
float plane(int x, int y) { return 0.001f * static_cast<float>(x) + 0.002f * static_cast<float>(y); }
float stepAt16(int x, int) { return x < 16 ? 0.5f : 0.25f; }
float parabola(int x, int) { return 1e-4f * static_cast<float>(x * x); }

void fillTile(const Texture2D& atlas, int tile, DepthFn depth) {
  std::vector<float> texels(kPage * kPage);
  for (int y = 0; y < kPage; ++y)
    for (int x = 0; x < kPage; ++x) texels[static_cast<size_t>(y * kPage + x)] = depth(x, y);
  glTextureSubImage3D(atlas.id(), 0, (tile % kPoolSide) * kPage, (tile / kPoolSide) * kPage, 0, kPage, kPage, 1, GL_RED,
                      GL_FLOAT, texels.data());
}

struct Bend {
  std::vector<float> texels;
  float at(int tile, int x, int y) const {
    const int ax = (tile % kPoolSide) * kPage + x, ay = (tile / kPoolSide) * kPage + y;
    return texels[static_cast<size_t>(ay * kSide + ax)];
  }
};

Bend readBend(GLuint texture) {
  Bend b{std::vector<float>(kSide * kSide)};
  glGetTextureImage(texture, 0, GL_RED, GL_FLOAT, static_cast<GLsizei>(b.texels.size() * sizeof(float)),
                    b.texels.data());
  return b;
}

TEST(VirtualDepthBend, MatchesSecondDifferencesWorkedByHandAndFollowsDrawnTiles) {
  test::GlHarness h;
  const Texture2D atlas = Texture2D::array(GL_R32F, kSide, kSide, 1, 1, "test depth atlas");
  fillTile(atlas, 0, plane);
  fillTile(atlas, 1, stepAt16);
  fillTile(atlas, 3, parabola);
  VirtualDepthBend bend;
  EXPECT_EQ(bend.update(h.shaders, nullptr, kPage, kPoolSide, kDefines), 0u) << "no atlas yet";
  bend.tilesDrawn({0, 1, 3});
  const GLuint texture = bend.update(h.shaders, &atlas, kPage, kPoolSide, kDefines);
  ASSERT_NE(texture, 0u);
  Bend b = readBend(texture);
  for (int y = 0; y < kPage; ++y)
    for (int x = 0; x < kPage; ++x) {
      EXPECT_NEAR(b.at(0, x, y), 0.0f, 1e-6f) << "plane at " << x << "," << y;
      // Both sides of the step bend by its height; a border texel takes its inner neighbour's.
      EXPECT_EQ(b.at(1, x, y), x == 15 || x == 16 ? 0.25f : 0.0f) << "step at " << x << "," << y;
      EXPECT_NEAR(b.at(3, x, y), 2e-4f, 1e-6f) << "parabola at " << x << "," << y;
    }

  // Tile 0 redrawn with the step: unchanged until it is marked drawn, then recomputed alone.
  fillTile(atlas, 0, stepAt16);
  fillTile(atlas, 3, plane);
  EXPECT_EQ(bend.update(h.shaders, &atlas, kPage, kPoolSide, kDefines), texture);
  EXPECT_NEAR(readBend(texture).at(0, 15, 5), 0.0f, 1e-6f);
  bend.tilesDrawn({0});
  bend.update(h.shaders, &atlas, kPage, kPoolSide, kDefines);
  b = readBend(texture);
  EXPECT_EQ(b.at(0, 15, 5), 0.25f);
  EXPECT_EQ(b.at(0, 16, 30), 0.25f);
  EXPECT_NEAR(b.at(3, 10, 10), 2e-4f, 1e-6f) << "tile 3 was not marked: its bend is last computed one";

  const Texture2D small = Texture2D::array(GL_R32F, kPage, kPage, 1, 1, "test atlas too small");
  EXPECT_EQ(bend.update(h.shaders, &small, kPage, kPoolSide, kDefines), 0u) << "an atlas smaller than the pool";
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
}

}  // namespace
}  // namespace sl
