// The blur's spans (blur_spans.h) against cases computed by hand: a rectangle and a triangle in a
// small map, with and without dilation, and the convex hull they start from.
#include "part/light_frame.h"
#include "prefiltered/blur_spans.h"
#include "prefiltered/tests/convex_inside.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <cmath>

namespace sl {
namespace {

using test::insideHull;

TEST(BlurSpans, AnUnknownHullCoversEveryTexel) {
  const std::vector<glm::ivec2> spans = blurSpans({}, 20, 8, 2.0f);
  ASSERT_EQ(spans.size(), 3u);  // bands of rows 0-7, 8-15, 16-19
  for (const glm::ivec2& s : spans) EXPECT_EQ(s, glm::ivec2(0, 19));
}

// uv [0.25, 0.75]² of a 64² map: texels 16..47 on both axes, the bands of rows 16..47 (2 to 5).
TEST(BlurSpans, ARectangleCoversItsTexelsAndTheDilation) {
  const std::vector<glm::vec2> square = {{0.25f, 0.25f}, {0.75f, 0.25f}, {0.75f, 0.75f}, {0.25f, 0.75f}};
  const std::vector<glm::ivec2> tight = blurSpans(square, 64, 8, 0.0f);
  ASSERT_EQ(tight.size(), 8u);
  for (int b = 0; b < 8; ++b)
    if (b >= 2 && b <= 5)
      EXPECT_EQ(tight[b], glm::ivec2(16, 47)) << b;
    else
      EXPECT_GT(tight[b].x, tight[b].y) << "band " << b << " misses the square";
  // Two texels more each way: columns 14..49, rows 14..49 reach bands 1 and 6.
  const std::vector<glm::ivec2> wide = blurSpans(square, 64, 8, 2.0f);
  for (int b = 1; b <= 6; ++b) EXPECT_EQ(wide[b], glm::ivec2(14, 49)) << b;
  EXPECT_GT(wide[0].x, wide[0].y);
  EXPECT_GT(wide[7].x, wide[7].y);
}

// The triangle (0,0), (1,0), (0,1) of a 16² map: x <= 16 - y. Rows 0..8 reach x = 16, rows 8..16
// reach x = 8 (their top edge), so the bands span columns 0..15 and 0..7.
TEST(BlurSpans, ATriangleNarrowsBandByBand) {
  const std::vector<glm::ivec2> spans = blurSpans({{0.0f, 0.0f}, {1.0f, 0.0f}, {0.0f, 1.0f}}, 16, 8, 0.0f);
  ASSERT_EQ(spans.size(), 2u);
  EXPECT_EQ(spans[0], glm::ivec2(0, 15));
  EXPECT_EQ(spans[1], glm::ivec2(0, 7));
}

// A 128² map (16² cells of 8², 2 groups of 8 cells along a run) where lookups read columns
// 20..27 of rows 40..47 alone (cells 2 and 3 of cell row 5). The second direction (runs down the
// columns) makes the groups of cell columns 2 and 3 over rows 0..63; the first (runs along the
// rows) makes what they read with a 5-texel kernel (2 rows past them: cell rows 0..8) in cell
// columns 0..7, its group 0.
TEST(BlurSpans, GroupsHoldTheReadTexelsAndWhatTheSecondDirectionReads) {
  std::vector<glm::ivec2> spans(16, glm::ivec2(1, 0));
  spans[5] = {20, 27};
  const BlurGroups g = blurGroups(spans, 128, 2);
  EXPECT_EQ(g.second, (std::vector<glm::uvec2>{{0, 2}, {0, 3}}));
  std::vector<glm::uvec2> first;
  for (unsigned row = 0; row <= 8; ++row) first.push_back({0, row});
  EXPECT_EQ(g.first, first);
  EXPECT_DOUBLE_EQ(g.share, 2.0 * 64 * 8 / (128.0 * 128.0));
  // Nothing read: no group runs.
  const BlurGroups none = blurGroups(std::vector<glm::ivec2>(16, glm::ivec2(1, 0)), 128, 2);
  EXPECT_TRUE(none.first.empty() && none.second.empty());
  EXPECT_EQ(none.share, 0.0);
}

TEST(BlurSpans, ConvexHullDropsInteriorAndCollinearPoints) {
  const std::vector<glm::vec2> hull =
      convexHull(std::vector<glm::vec2>{{0, 0}, {1, 0}, {2, 0}, {2, 2}, {0, 2}, {1, 1}, {0.5f, 1.5f}, {0, 0}, {0, 1}});
  ASSERT_EQ(hull.size(), 4u);
  float area = 0.0f;  // counter-clockwise: positive shoelace area
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::vec2 a = hull[i], b = hull[(i + 1) % hull.size()];
    area += 0.5f * (a.x * b.y - b.x * a.y);
  }
  EXPECT_FLOAT_EQ(area, 4.0f);
}

// An orthographic view's hull is the projected points' own hull: a square's corners and its
// centre give the square's four corners in uv.
TEST(BlurSpans, ReceiverHullOfAnOrthographicViewIsTheProjectedCorners) {
  LightView v;
  v.view = glm::lookAt(glm::vec3(0.0f, 10.0f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f));
  v.proj = glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, 0.1f, 20.0f);
  v.viewProj = v.proj * v.view;
  const std::vector<glm::vec2> hull =
      receiverHullInMap(v, {{-2, 0, -2}, {2, 0, -2}, {2, 0, 2}, {-2, 0, 2}, {0, 0, 0}, {1, 3, 1}});
  ASSERT_EQ(hull.size(), 4u);
  for (const glm::vec2& q : hull) {
    EXPECT_NEAR(std::abs(q.x - 0.5f), 0.25f, 1e-6f);
    EXPECT_NEAR(std::abs(q.y - 0.5f), 0.25f, 1e-6f);
  }
}

// A spot's body may reach behind the light: the hull holds every point in front (here one on
// the axis and one at the frustum's edge) and the segments' crossings just in front of the light
// (far out in uv), and is empty when the whole body is behind.
TEST(BlurSpans, ReceiverHullOfASpotHoldsThePartInFrontOfTheLight) {
  LightView v;
  v.perspective = true;
  v.nearPlane = 0.1f;
  v.farPlane = 10.0f;
  v.view = glm::lookAt(glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f), glm::vec3(0.0f, 1.0f, 0.0f));
  v.proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f);
  v.viewProj = v.proj * v.view;
  const std::vector<glm::vec3> body = {{0, 0, -2}, {2, 0, -2}, {0, 1, -2}, {0, 0, 3}};
  const std::vector<glm::vec2> hull = receiverHullInMap(v, body);
  ASSERT_GE(hull.size(), 3u);
  EXPECT_TRUE(insideHull(hull, {0.5f, 0.5f}, 1e-4f));
  EXPECT_TRUE(insideHull(hull, {1.0f, 0.5f}, 1e-4f));
  EXPECT_TRUE(insideHull(hull, {0.5f, 0.75f}, 1e-4f));
  for (const glm::vec2& q : hull) EXPECT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
  float reach = 0.0f;  // the crossing toward (2, 0, -2) lands far beyond the map's right edge
  for (const glm::vec2& q : hull) reach = std::max(reach, q.x);
  EXPECT_GT(reach, 100.0f);
  EXPECT_TRUE(receiverHullInMap(v, {{0, 0, 1}, {1, 1, 2}}).empty());
}

// The summed-area tables' columns (columnIntervals): per column, the rows whose span holds it,
// against a direct count; a set of spans whose column is broken into two runs has none.
TEST(BlurSpans, ColumnIntervalsOfATriangleAreTheRowsHoldingEachColumn) {
  const int n = 64;
  const std::vector<glm::ivec2> rows = blurSpans({{0.3f, 0.15f}, {0.85f, 0.4f}, {0.35f, 0.8f}}, n, 1, 3.0f);
  const auto columns = columnIntervals(rows, n);
  ASSERT_TRUE(columns.has_value());
  for (int x = 0; x < n; ++x) {
    int first = n, last = -1;
    for (int y = 0; y < n; ++y)
      if (x >= rows[static_cast<size_t>(y)].x && x <= rows[static_cast<size_t>(y)].y)
        first = std::min(first, y), last = y;
    const glm::ivec2 want = last < 0 ? glm::ivec2(1, 0) : glm::ivec2(first, last);
    EXPECT_EQ((*columns)[static_cast<size_t>(x)], want) << "column " << x;
  }
  EXPECT_EQ((*columns)[0], glm::ivec2(1, 0));  // left of the dilated triangle
  // By hand, texels [30, 31) in x: the top edge (19.2, 9.6)-(54.4, 25.6), slope 16 / 35.2, moved
  // by the dilation's corner (3, -3), is at y = 10.15 at x = 30; the bottom edge (54.4, 25.6)-
  // (22.4, 51.2), slope -0.8, moved by (3, 3), at y = 50.52.
  EXPECT_EQ((*columns)[30], glm::ivec2(10, 50));
  std::vector<glm::ivec2> broken(static_cast<size_t>(n), glm::ivec2(1, 0));
  broken[10] = broken[12] = glm::ivec2(5, 8);  // column 5 in rows 10 and 12, not 11
  EXPECT_FALSE(columnIntervals(broken, n).has_value());
}

}  // namespace
}  // namespace sl
