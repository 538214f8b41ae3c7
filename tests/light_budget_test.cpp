// The budget of maps across several lights (app/render/light_budget.h): footprints against areas
// computed by hand, and the allocation's bounds.
#include "render/light_budget.h"

#include <glm/gtc/matrix_transform.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

namespace sl {
namespace {

// A camera at the origin looking down -z, 90° square: at distance d the screen spans ±d.
struct Camera90 {
  glm::mat4 view{1.0f};
  glm::mat4 proj = glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
};

Bounds box(glm::vec3 lo, glm::vec3 hi) {
  Bounds b;
  b.add(lo);
  b.add(hi);
  return b;
}

Light pointLight(glm::vec3 position, float range) {
  Light l;
  l.type = Light::Type::Point;
  l.position = position;
  l.range = range;
  return l;
}

TEST(LightBudget, FootprintIsTheReachsProjectedArea) {
  const Camera90 cam;
  // The scene [-1,1]² × [-3,-2]: its near face at distance 2 spans ±0.5 of the screen, a quarter.
  const Bounds scene = box({-1, -1, -3}, {1, 1, -2});
  Light sun;
  EXPECT_NEAR(lightFootprint(sun, scene, cam.view, cam.proj), 0.25, 1e-5);
  // A point light without a range reaches the whole scene.
  EXPECT_NEAR(lightFootprint(pointLight({0, 0, -2.5f}, 0.0f), scene, cam.view, cam.proj), 0.25, 1e-5);
  // Range 0.25 at depth 2.5: its box's near face at 2.25 spans ±0.25 / 2.25.
  const double side = 0.25 / 2.25;
  EXPECT_NEAR(lightFootprint(pointLight({0, 0, -2.5f}, 0.25f), scene, cam.view, cam.proj), side * side, 1e-5);
  // Cut by the scene: range 2 reaches past it on every side, so the scene's quarter again.
  EXPECT_NEAR(lightFootprint(pointLight({0, 0, -2.5f}, 2.0f), scene, cam.view, cam.proj), 0.25, 1e-5);
}

TEST(LightBudget, ALightReachingNothingInViewHasNoFootprint) {
  const Camera90 cam;
  const Bounds scene = box({-10, -1, -10}, {10, 1, 10});
  // Beside the frustum (at depth 2.5 it spans x within ±2.5), behind the camera, outside the scene.
  EXPECT_EQ(lightFootprint(pointLight({8, 0, -2.5f}, 0.5f), scene, cam.view, cam.proj), 0.0);
  EXPECT_EQ(lightFootprint(pointLight({0, 0, 5}, 1.0f), scene, cam.view, cam.proj), 0.0);
  EXPECT_EQ(lightFootprint(pointLight({0, 5, -3}, 1.0f), scene, cam.view, cam.proj), 0.0);
  // Reaching into the frustum by a little: a small footprint, never 0.
  const double edge = lightFootprint(pointLight({3.2f, 0, -2.5f}, 0.8f), scene, cam.view, cam.proj);
  EXPECT_GT(edge, 0.0);
  EXPECT_LT(edge, 0.05);
}

TEST(LightBudget, NoBudgetGivesEveryDrawnLightTheFullSize) {
  const std::vector<int> sizes = budgetMapSizes({{0.5, 6}, {0.0, 6}, {1.0, 1}}, 0.0, 1024, 64);
  EXPECT_EQ(sizes, (std::vector<int>{1024, 0, 1024}));
}

TEST(LightBudget, ABudgetSplitByHandStaysOnTheLadder) {
  // From 64² each, doubled by footprint per texel: 3:1 footprints give 512 and 512 within
  // 1024² + 256² texels (1024 and 256 would be the 3:1 nearest to proportional, but the greedy
  // doubling stops when the larger light's next step does not fit).
  EXPECT_EQ(budgetMapSizes({{0.75, 1}, {0.25, 1}}, 1024.0 * 1024 + 256 * 256, 1024, 64), (std::vector<int>{512, 512}));
  // Four equal cubes within four times 6 × 512²: each 512.
  EXPECT_EQ(budgetMapSizes({{0.3, 6}, {0.3, 6}, {0.3, 6}, {0.3, 6}}, 4.0 * 6 * 512 * 512, 1024, 64),
            (std::vector<int>{512, 512, 512, 512}));
  // The ladder of a size that is not a power of two: 1254 halved.
  EXPECT_EQ(budgetMapSizes({{1.0, 4}}, 4.0 * 313 * 313, 1254, 64), (std::vector<int>{313}));
  // A budget below the smallest steps: every drawn light at its smallest (78 = 1254 >> 4).
  EXPECT_EQ(budgetMapSizes({{1.0, 4}, {0.2, 4}}, 10.0, 1254, 64), (std::vector<int>{78, 78}));
}

TEST(LightBudget, RandomDemandsStayWithinTheBudgetAndFollowTheFootprint) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    const int layers = trial % 2 ? 6 : 4;
    std::vector<LightDemand> lights(1 + trial % 16);
    for (LightDemand& l : lights) l = {unit(rng) < 0.1 ? 0.0 : unit(rng), layers};
    const double budget = 1e6 * (1 + trial % 40);
    const std::vector<int> sizes = budgetMapSizes(lights, budget, 1024, 64);
    ASSERT_EQ(sizes.size(), lights.size());
    double smallest = 0.0;
    for (const LightDemand& l : lights) smallest += l.footprint > 0.0 ? double(l.layers) * 64 * 64 : 0.0;
    EXPECT_LE(budgetedTexels(lights, sizes), std::max(budget, smallest)) << "trial " << trial;
    for (size_t a = 0; a < lights.size(); ++a) {
      if (lights[a].footprint == 0.0) {
        EXPECT_EQ(sizes[a], 0);
        continue;
      }
      EXPECT_TRUE(sizes[a] >= 64 && sizes[a] <= 1024 && (1024 % sizes[a]) == 0) << sizes[a];
      for (size_t b = 0; b < lights.size(); ++b)
        if (lights[a].footprint > lights[b].footprint && lights[b].footprint > 0.0)
          EXPECT_GE(sizes[a], sizes[b]) << "trial " << trial << ": more footprint, fewer texels";
    }
  }
}

TEST(LightBudget, HeldFootprintMovesOnlyBeyondItsBand) {
  EXPECT_EQ(heldFootprint(0.0, 0.2), 0.2);    // first measure: at once
  EXPECT_EQ(heldFootprint(0.2, 0.0), 0.0);    // reaching nothing in view: at once (not drawn)
  EXPECT_EQ(heldFootprint(0.2, 0.25), 0.2);   // within 1.5x: held
  EXPECT_EQ(heldFootprint(0.2, 0.14), 0.2);   // within 1/1.5
  EXPECT_EQ(heldFootprint(0.2, 0.31), 0.31);  // beyond: the new one
  EXPECT_EQ(heldFootprint(0.2, 0.13), 0.13);
}

// A camera hovering where the allocation steps: the footprint of one lamp swings by 3 % either
// side of the value where its maps change size. Without the hold the sizes switch every frame
// (each switch re-allocates the lamp's maps); held, they stay.
TEST(LightBudget, AFootprintHoveringAtAStepDoesNotSwitchTheSizesEveryFrame) {
  const double budget = 6.0 * (256 * 256 + 128 * 128);
  auto sizesAt = [&](double a) { return budgetMapSizes({{a, 6}, {0.3, 6}}, budget, 1024, 64); };
  double step = 0.0;  // a footprint where the sizes differ 3 % below and above it
  for (double a = 0.05; a < 1.0 && step == 0.0; a += 0.001)
    if (sizesAt(a * 0.97) != sizesAt(a * 1.03)) step = a;
  ASSERT_GT(step, 0.0) << "no step in the allocation to hover at";
  int switchesRaw = 0, switchesHeld = 0;
  double held = 0.0;
  std::vector<int> lastRaw, lastHeld;
  for (int frame = 0; frame < 20; ++frame) {
    const double now = step * (frame % 2 ? 1.03 : 0.97);
    held = heldFootprint(held, now);
    const std::vector<int> raw = sizesAt(now), kept = sizesAt(held);
    if (frame > 0) {
      switchesRaw += raw != lastRaw;
      switchesHeld += kept != lastHeld;
    }
    lastRaw = raw;
    lastHeld = kept;
  }
  EXPECT_EQ(switchesRaw, 19);
  EXPECT_EQ(switchesHeld, 0);
}

// Squares inside the layer and apart, in a layer no larger than the quadtree over cells of the
// largest square would make (the square of whole cells, which packs a ladder without gaps) and
// no smaller than their area.
void expectPackedApart(const std::vector<int>& sides, const AtlasRegions& a, const std::string& what) {
  double area = 0.0;
  int largest = 0;
  for (int s : sides) {
    area += double(std::max(s, 0)) * std::max(s, 0);
    largest = std::max(largest, s);
  }
  if (largest == 0) {
    EXPECT_EQ(a.side, 0) << what;
    return;
  }
  const int cells = int(std::ceil(area / (double(largest) * largest) - 1e-9));
  int n = 1;
  while (n * n < cells) ++n;
  EXPECT_LE(a.side, (n * largest + 7) / 8 * 8) << what;
  EXPECT_GE(double(a.side) * a.side, area) << what;
  ASSERT_EQ(a.rects.size(), sides.size());
  for (size_t i = 0; i < sides.size(); ++i) {
    const glm::ivec4 r = a.rects[i];
    if (sides[i] <= 0) {
      EXPECT_EQ(r, glm::ivec4(0)) << what;
      continue;
    }
    EXPECT_EQ(r.z, sides[i]) << what << ": every square placed";
    EXPECT_EQ(r.w, sides[i]) << what;
    EXPECT_TRUE(r.x >= 0 && r.y >= 0 && r.x + r.z <= a.side && r.y + r.w <= a.side) << what << " " << i;
    for (size_t j = 0; j < i; ++j) {
      const glm::ivec4 q = a.rects[j];
      if (q.z <= 0) continue;
      EXPECT_TRUE(r.x + r.z <= q.x || q.x + q.z <= r.x || r.y + r.w <= q.y || q.y + q.w <= r.y)
          << what << ": " << i << " overlaps " << j;
    }
  }
}

TEST(LightBudget, AtlasRegionsPackTheLadderApartInTheSmallestSquare) {
  for (const std::vector<int>& sides : std::vector<std::vector<int>>{
           {}, {0, 0}, {1024}, {256, 1024, 0, 512, 256}, {512, 512, 512, 512}, {1000, 500, 250, 125, 62, 62, 62, 62}})
    expectPackedApart(sides, packAtlasRegions(sides), "by hand");
  EXPECT_EQ(packAtlasRegions({1024}).side, 1024);
  EXPECT_EQ(packAtlasRegions({512, 512, 512, 512}).side, 1024);  // four in a square without a gap
  // A map and three of half its side: an L around it, 1.5 times its side (a square of whole
  // cells of the largest would be twice, four times the texels of the L's 1.29).
  EXPECT_EQ(packAtlasRegions({2508, 1254, 1254, 1254}).side, 3768);
  std::mt19937 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<int> sides(1 + rng() % 16);
    for (int& s : sides) s = (rng() % 5 == 0) ? 0 : 2048 >> (rng() % 6);
    expectPackedApart(sides, packAtlasRegions(sides), "trial " + std::to_string(trial));
  }
}

// The room left in the atlas goes to the lights in it, most footprint per texel first, on the
// ladder, never past the largest map nor out of the square; a light outside keeps its size.
TEST(LightBudget, AtlasSizesGrowIntoTheRoomLeftInTheSquare) {
  // 1254, 1254, 1254, 627 under 2508: a square of 2512 (two 1254 a row), room for a fourth 1254.
  const std::vector<LightDemand> lights = {{0.4, 1}, {0.3, 1}, {0.2, 1}, {0.1, 1}, {0.5, 6}};
  std::vector<bool> inAtlas = {true, true, true, true, false};
  const std::vector<int> grown = fillAtlasSizes(lights, {1254, 1254, 1254, 627, 313}, inAtlas);
  EXPECT_EQ(grown, (std::vector<int>{1254, 1254, 1254, 1254, 313}));
  // Two of 313 beside the third 1254: each grows to 627 (two fit in the 1258 texels beside it),
  // not to 1254 (no room for one).
  std::vector<bool> five(5, true);
  const std::vector<int> twoGrow =
      fillAtlasSizes({{0.1, 1}, {0.1, 1}, {0.1, 1}, {0.5, 1}, {0.1, 1}}, {1254, 1254, 1254, 313, 313}, five);
  EXPECT_EQ(twoGrow, (std::vector<int>{1254, 1254, 1254, 627, 627}));
  // 627 and 156 side by side in 784: no room for 313.
  std::vector<bool> two = {true, true};
  EXPECT_EQ(fillAtlasSizes({{0.1, 1}, {0.9, 1}}, {627, 156}, two), (std::vector<int>{627, 156}));
  std::mt19937 rng(11);
  for (int trial = 0; trial < 100; ++trial) {
    std::vector<LightDemand> d(1 + rng() % 12);
    std::vector<int> sizes;
    std::vector<bool> in;
    for (LightDemand& l : d) {
      l.footprint = 0.01 + (rng() % 100) / 100.0;
      sizes.push_back(2048 >> (rng() % 5));
      in.push_back(rng() % 4 != 0);
    }
    std::vector<bool> inAfter = in;
    const std::vector<int> g = fillAtlasSizes(d, sizes, inAfter);
    ASSERT_EQ(inAfter, in);
    std::vector<int> before(sizes.size(), 0), after(sizes.size(), 0);
    int largest = 0;
    for (size_t k = 0; k < sizes.size(); ++k) {
      before[k] = in[k] ? sizes[k] : 0;
      after[k] = in[k] ? g[k] : 0;
      largest = std::max(largest, before[k]);
      if (!in[k]) EXPECT_EQ(g[k], sizes[k]) << trial;
      EXPECT_GE(g[k], sizes[k]) << trial;
    }
    for (size_t k = 0; k < sizes.size(); ++k) {
      EXPECT_LE(after[k], largest) << trial;
      EXPECT_EQ(largest % std::max(after[k], 1), 0) << trial << ": on the ladder";
    }
    EXPECT_LE(packAtlasRegions(after).side, packAtlasRegions(before).side) << trial;
  }
}

}  // namespace
}  // namespace sl
