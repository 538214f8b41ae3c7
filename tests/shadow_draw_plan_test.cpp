// The shadow pass's plan is data: which stages draw the casters follows the light views'
// projection kinds, and a tile's clip matrix is its page transform. No GPU needed.
#include "part/shadow_draw_plan.h"
#include "techniques/technique.h"

#include <gtest/gtest.h>

namespace sl {

namespace {
LightSpace spaceOf(std::vector<LightView::Projection> kinds) {
  LightSpace ls;
  for (auto k : kinds) {
    LightView v;
    v.projection = k;
    ls.views.push_back(v);
  }
  return ls;
}
}  // namespace

TEST(ShadowDrawPlan, WarpedViewsTessellateTheCastersMatrixViewsDoNot) {
  using P = LightView::Projection;
  const auto plain = casterStages(spaceOf({P::Matrix, P::Matrix}), "passes/shadow.frag");
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain.back().second, "passes/shadow.frag");
  const auto warped = casterStages(spaceOf({P::LogWarp}), "passes/shadow_custom.frag");
  ASSERT_EQ(warped.size(), 4u);
  EXPECT_EQ(warped[1].first, static_cast<GLenum>(GL_TESS_CONTROL_SHADER));
  EXPECT_EQ(warped[2].first, static_cast<GLenum>(GL_TESS_EVALUATION_SHADER));
  EXPECT_EQ(warped.back().second, "passes/shadow_custom.frag");
}

// Only the log warp's views sort their casters before tessellating (logpsm.sort_casters);
// the sorted plain triangles are drawn by the same stages without the tessellation ones.
TEST(ShadowDrawPlan, OnlyLogWarpedViewsSortTheirCastersOutOfTessellation) {
  using P = LightView::Projection;
  LightSpace sorting = spaceOf({P::Matrix, P::LogWarp});
  EXPECT_EQ(casterSortStage(sorting), "");  // the view does not ask for it
  sorting.views.back().sortCasters = true;
  EXPECT_EQ(casterSortStage(sorting), "passes/warp_classify.comp");
  LightSpace others = spaceOf({P::Matrix, P::Paraboloid});
  for (LightView& v : others.views) v.sortCasters = true;
  EXPECT_EQ(casterSortStage(others), "");
  const auto plain = withoutTessellation(casterStages(spaceOf({P::LogWarp}), "passes/shadow.frag"));
  ASSERT_EQ(plain.size(), 2u);
  EXPECT_EQ(plain[0].second, "passes/shadow.vert");
  EXPECT_EQ(plain[1].second, "passes/shadow.frag");
}

TEST(ShadowDrawPlan, TileClipIsItsPageTransformAfterTheLayer) {
  ShadowTile tile;
  tile.transform = glm::vec4(4.0f, 4.0f, 1.0f, -3.0f);  // a quarter-size page, offset
  const glm::mat4 layer = glm::mat4(2.0f);
  const glm::vec4 p(0.3f, -0.2f, 0.5f, 1.0f);
  const glm::vec4 c = layer * p;
  const glm::vec4 expected(c.x * 4.0f + c.w * 1.0f, c.y * 4.0f - c.w * 3.0f, c.z, c.w);
  const glm::vec4 got = tile.clip(layer) * p;
  for (int k = 0; k < 4; ++k) EXPECT_NEAR(got[k], expected[k], 1e-5f);
}

// What the parts declare: the deep map draws opaque casters only, moment maps depth alone like a
// depth map (their filter pass makes the moments), and the log warp's views ask for
// tessellation (no hooks: the plan's data).
TEST(ShadowDrawPlan, PartsDeclareTheirShareAsData) {
  EXPECT_EQ(findRepresentation("deep")->casterDraw().casters, CasterSet::Opaque);
  EXPECT_EQ(findRepresentation("depth-nearest")->casterDraw().casters, CasterSet::All);
  EXPECT_EQ(findRepresentation("vsm")->casterDraw().fragment, "passes/shadow.frag");
  EXPECT_EQ(findRepresentation("vssm")->casterDraw().fragment, "passes/shadow.frag");
  EXPECT_EQ(findRepresentation("depth-pcf")->casterDraw().fragment, "passes/shadow.frag");
}

}  // namespace sl
