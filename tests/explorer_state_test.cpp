// Explorer state changes that need no window: the light-direction control.
#include "explorer/explorer_state.h"
#include "explorer/param_panel.h"
#include "explorer/plot_window.h"
#include "explorer/viewport_area.h"
#include "scene/scene.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace sl {
namespace {

TEST(ExplorerLight, AnglesRoundTrip) {
  for (float az : {-170.0f, -45.0f, 0.0f, 30.0f, 120.0f})
    for (float el : {-30.0f, 5.0f, 45.0f, 80.0f}) {
      Light light;
      light.direction = directionFromLightAngles(az, el);
      EXPECT_NEAR(glm::length(light.direction), 1.0f, 1e-5f);
      const glm::vec2 back = lightAngles(light);
      EXPECT_NEAR(back.x, az, 1e-3f) << az << " " << el;
      EXPECT_NEAR(back.y, el, 1e-3f) << az << " " << el;
    }
  // Elevation 90: straight down, whatever the azimuth.
  const glm::vec3 down = directionFromLightAngles(77.0f, 90.0f);
  EXPECT_NEAR(down.y, -1.0f, 1e-6f);
}

TEST(ExplorerLight, ChangingTheLightIsACut) {
  ExplorerState state;
  state.scene = std::make_unique<Scene>(loadScene("basic", defaultAssetsDir()));
  state.cutPending = false;
  const glm::vec3 before = state.scene->light.direction;

  // Bad input changes nothing.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(setLightDirection(state, glm::vec3(0.0f)));
  EXPECT_FALSE(setLightDirection(state, glm::vec3(nan, -1.0f, 0.0f)));
  EXPECT_FALSE(setLightDirection(state, before));  // the same direction
  EXPECT_EQ(state.scene->light.direction, before);
  EXPECT_FALSE(state.cutPending);

  EXPECT_TRUE(setLightDirection(state, glm::vec3(0.0f, -2.0f, 0.0f)));
  EXPECT_NEAR(state.scene->light.direction.y, -1.0f, 1e-6f);  // normalised
  EXPECT_TRUE(state.cutPending);                              // accumulated history belongs to the old light
}

TEST(ExplorerLight, MovingAPointLightIsACutAndASunHasNoPosition) {
  ExplorerState state;
  state.scene = std::make_unique<Scene>(loadScene("basic", defaultAssetsDir()));
  state.cutPending = false;
  EXPECT_FALSE(setLightPosition(state, glm::vec3(1.0f, 2.0f, 3.0f))) << "basic's sun has no position to move";
  EXPECT_FALSE(state.cutPending);
  state.scene = std::make_unique<Scene>(loadScene("street", defaultAssetsDir()));
  const glm::vec3 before = state.scene->light.position;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(setLightPosition(state, glm::vec3(nan, 1.0f, 0.0f)));
  EXPECT_FALSE(setLightPosition(state, before));  // the same place
  EXPECT_EQ(state.scene->light.position, before);
  EXPECT_FALSE(state.cutPending);
  EXPECT_TRUE(setLightPosition(state, before + glm::vec3(0.5f, 0.0f, 0.0f)));
  EXPECT_EQ(state.scene->light.position, before + glm::vec3(0.5f, 0.0f, 0.0f));
  EXPECT_TRUE(state.cutPending);
}

// street-lamps: the views show one light at a time; another shadowed one can take its place (the
// drag fields then move it), and an other light's shadow can be turned off, each a cut.
TEST(ExplorerState, ALightOfSeveralIsShownOrUnshadowed) {
  ExplorerState state;
  state.scene = std::make_unique<Scene>(loadScene("street-lamps", defaultAssetsDir()));
  state.cutPending = false;
  const Light first = state.scene->light, second = state.scene->otherLights[0];
  EXPECT_FALSE(showLightInViews(state, 3)) << "street-lamps has 3 other lights";
  EXPECT_FALSE(state.cutPending);
  EXPECT_TRUE(showLightInViews(state, 0));
  EXPECT_EQ(state.scene->light.position, second.position);
  EXPECT_EQ(state.scene->otherLights[0].position, first.position);
  EXPECT_TRUE(state.cutPending);
  state.cutPending = false;
  EXPECT_TRUE(setOtherLightShadow(state, 1, false));
  EXPECT_FALSE(state.scene->otherLights[1].shadow);
  EXPECT_TRUE(state.cutPending);
  state.cutPending = false;
  EXPECT_FALSE(setOtherLightShadow(state, 1, false)) << "already off";
  EXPECT_FALSE(showLightInViews(state, 1)) << "an unshadowed light has no maps to show";
  EXPECT_FALSE(state.cutPending);
}

// The panel shows the several-light parameters (lights.shadowed, lights.texel_budget,
// lights.one_atlas) only in a scene of several lights.
TEST(ExplorerState, LightParametersShowOnlyInScenesOfSeveralLights) {
  const Technique t = makeTechnique("cube");
  const Scene lamps = loadScene("street-lamps", defaultAssetsDir()), one = loadScene("street", defaultAssetsDir());
  EXPECT_TRUE(paramsWithoutEffect(t.params, &lamps).empty());
  const std::set<std::string> hidden = paramsWithoutEffect(t.params, &one);
  EXPECT_EQ(hidden, (std::set<std::string>{"lights.one_atlas", "lights.shadowed", "lights.texel_budget"}));
  EXPECT_FALSE(hidden.count("shadowmap.size"));
}

}  // namespace
// A tour step's caption reads "left, middle, right" for three viewports: they sit in one row of
// equal tiles, and only four make a 2x2 grid.
TEST(ExplorerLayout, ThreeViewportsSitInOneRowFourInTwo) {
  ImGui::CreateContext();
  for (int n = 1; n <= 4; ++n) EXPECT_EQ(viewportCountFor(size_t(n)), n);
  EXPECT_EQ(viewportCountFor(0), 1);
  EXPECT_EQ(viewportCountFor(7), kMaxViewports);
  const ImVec2 area(1200, 600);
  const MainAreaLayout three = layoutMainArea(ImVec2(0, 0), area, 3, 0, ImVec2(1, 1));
  ASSERT_EQ(three.tiles.size(), 3u);
  for (size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(three.tiles[i].headerMin.y, three.tiles[0].headerMin.y) << i;
    EXPECT_NEAR(three.tiles[i].headerSize.x, area.x / 3, 10.0f) << i;
    EXPECT_LE(three.tiles[i].headerMin.x + three.tiles[i].headerSize.x, area.x) << i;
    if (i) EXPECT_GT(three.tiles[i].headerMin.x, three.tiles[i - 1].headerMin.x + three.tiles[i - 1].headerSize.x - 1);
  }
  const MainAreaLayout four = layoutMainArea(ImVec2(0, 0), area, 4, 0, ImVec2(1, 1));
  ASSERT_EQ(four.tiles.size(), 4u);
  EXPECT_EQ(four.tiles[1].headerMin.y, four.tiles[0].headerMin.y);
  EXPECT_GT(four.tiles[2].headerMin.y, four.tiles[0].headerMin.y);
  EXPECT_EQ(four.tiles[2].headerMin.x, four.tiles[0].headerMin.x);
  ImGui::DestroyContext();
}

}  // namespace sl

namespace sl {

// #23: the plot strip's legend ran past its edge. Entries flow and wrap within the width.
TEST(ExplorerLayout, PlotLegendEntriesWrapWithinTheWidth) {
  const std::vector<float> widths = {90, 120, 60, 200, 80, 400};
  const std::vector<ImVec2> at = flowLegend(widths, 300.0f, 20.0f);
  ASSERT_EQ(at.size(), widths.size());
  for (size_t k = 0; k < at.size(); ++k)
    if (widths[k] <= 300.0f) EXPECT_LE(at[k].x + widths[k], 300.0f) << "entry " << k << " passes the edge";
  EXPECT_EQ(at[0].y, 0.0f);
  EXPECT_EQ(at[2].y, 0.0f);   // 90 + 120 + 60 fit one row
  EXPECT_EQ(at[3].y, 20.0f);  // 200 wraps
  EXPECT_EQ(at[4].y, 20.0f);  // 200 + 80
  EXPECT_EQ(at[5].x, 0.0f);   // wider than the whole width: a row of its own
  EXPECT_EQ(at[5].y, 40.0f);
}

}  // namespace sl
