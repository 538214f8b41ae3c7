// The GL-free logic of the explorer's accuracy panel: rest detection, the Pareto front, chart
// axes, per-viewport cost from pass timings and configuration strings.
#include "explorer/error_panel.h"

#include "technique.h"

#include <gtest/gtest.h>

#include <cmath>

namespace {

sl::RestKey keyAt(float x, double time = 0.0) {
  sl::RestKey k;
  k.camera.position = glm::vec3(x, 2, 5);
  k.width = 640;
  k.height = 360;
  k.time = time;
  k.sceneGeneration = 1;
  return k;
}

}  // namespace

TEST(ExplorerErrorPanel, RestsAfterTheKeyStaysTheSameLongEnough) {
  sl::RestDetector rest(0.3);
  EXPECT_FALSE(rest.update(keyAt(0), 0.0));
  EXPECT_FALSE(rest.update(keyAt(0), 0.2));
  EXPECT_TRUE(rest.update(keyAt(0), 0.31));
  // Moving the camera restarts the wait and says why.
  EXPECT_FALSE(rest.update(keyAt(1), 0.4));
  EXPECT_TRUE(rest.lastChange().camera);
  EXPECT_FALSE(rest.lastChange().time);
  EXPECT_FALSE(rest.update(keyAt(1), 0.6));
  EXPECT_TRUE(rest.update(keyAt(1), 0.75));
  // Running time (an animated scene) is motion too.
  EXPECT_FALSE(rest.update(keyAt(1, 0.5), 0.8));
  EXPECT_TRUE(rest.lastChange().time);
  // A rounding-level difference in the pose is not motion.
  EXPECT_TRUE(rest.update(keyAt(1.0000001f, 0.5), 1.2));
}

TEST(ExplorerErrorPanel, SizeAndSceneChangesAreNotTheSameView) {
  sl::RestKey a = keyAt(0), b = keyAt(0);
  EXPECT_TRUE(sl::sameRestKey(a, b));
  b.width = 641;
  EXPECT_TRUE(sl::compareRestKeys(a, b).size);
  b = a;
  b.sceneGeneration = 2;
  EXPECT_TRUE(sl::compareRestKeys(a, b).scene);
  b = a;
  b.camera.fovDeg = 50;
  EXPECT_TRUE(sl::compareRestKeys(a, b).camera);
}

TEST(ExplorerErrorPanel, ParetoFrontKeepsOnlyUnbeatenPoints) {
  std::vector<sl::ChartPoint> points = {{"slow and good", 10.0, 0.5},     {"fast and bad", 1.0, 8.0},
                                        {"dominated", 6.0, 9.0},          {"middle", 4.0, 2.0},
                                        {"tie in time, worse", 4.0, 3.0}, {"slow and worse", 12.0, 0.5}};
  const std::vector<size_t> front = sl::paretoFront(points);
  ASSERT_EQ(front.size(), 3u);
  EXPECT_EQ(points[front[0]].config, "fast and bad");
  EXPECT_EQ(points[front[1]].config, "middle");
  EXPECT_EQ(points[front[2]].config, "slow and good");
  EXPECT_TRUE(sl::paretoFront({}).empty());
}

TEST(ExplorerErrorPanel, RecordingTheSameConfigurationKeepsTheMedianErrorAndTheMedianTime) {
  std::vector<sl::ChartPoint> points;
  sl::recordChartPoint(points, {"pcf", 2.0, 5.0, 0, 4.0, {}});
  sl::recordChartPoint(points, {"vsm", 3.0, 4.0, 1, 3.0, {}});
  sl::recordChartPoint(points, {"pcf", 2.5, 1.0, 1, 0.5, {}});
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].config, "pcf");
  EXPECT_DOUBLE_EQ(points[0].ms, 2.25);       // median of 2.0 and 2.5
  EXPECT_DOUBLE_EQ(points[0].wrongPct, 3.0);  // median of 5 and 1
  EXPECT_DOUBLE_EQ(points[0].imageWrongPct, 2.25);
  EXPECT_EQ(points[0].viewport, 1);
  // A slow reading (a shader rebuilt, the machine busy) does not move the point; the latest
  // reading alone would have.
  sl::recordChartPoint(points, {"pcf", 40.0, 1.0, 1, 0.5, {}});
  EXPECT_DOUBLE_EQ(points[0].ms, 2.5);
  EXPECT_DOUBLE_EQ(points[0].wrongPct, 1.0);  // median of 5, 1, 1
  EXPECT_EQ(points[0].msReadings.size(), 3u);
  EXPECT_DOUBLE_EQ(points[1].ms, 3.0);  // the other configuration is untouched
  // Only the latest readings are kept: a configuration whose cost really changed (the window
  // resized) follows within kChartReadingsKept measurements.
  for (size_t i = 0; i < sl::kChartReadingsKept; ++i) sl::recordChartPoint(points, {"pcf", 7.0, 1.0, 1, 0.5, {}});
  EXPECT_EQ(points[0].msReadings.size(), sl::kChartReadingsKept);
  EXPECT_DOUBLE_EQ(points[0].ms, 7.0);
}

// The drifting Pareto points: a configuration whose error flickers from one measurement
// to the next (pixel-correct while it converges, a jittered map) holds still on the chart, and
// one outlier does not move it; a real change (it converged) is followed within a few readings.
TEST(ExplorerErrorPanel, ChartPointsHoldStillWhileReadingsFlicker) {
  std::vector<sl::ChartPoint> points;
  const double flicker[] = {2.0, 2.2, 1.9, 9.0, 2.1, 2.0, 2.3, 1.8, 2.1};
  std::vector<double> shown;
  for (double e : flicker) {
    sl::recordChartPoint(points, {"pc", 3.0, e, 0, e, {}});
    shown.push_back(points[0].wrongPct);
  }
  // After the window has filled, every shown value stays within the flicker's normal band,
  // the 9.0 outlier included.
  for (size_t i = 2; i < shown.size(); ++i) {
    EXPECT_GE(shown[i], 1.9) << i;
    EXPECT_LE(shown[i], 2.2) << i;
  }
  EXPECT_LE(points[0].wrongReadings.size(), sl::kChartErrorReadings);
  for (size_t i = 0; i < sl::kChartErrorReadings; ++i) sl::recordChartPoint(points, {"pc", 3.0, 0.1, 0, 0.1, {}});
  EXPECT_DOUBLE_EQ(points[0].wrongPct, 0.1);
  // An image error that could not be measured (NaN) keeps the last good one.
  sl::recordChartPoint(points, {"pc", 3.0, 0.1, 0, std::nan(""), {}});
  EXPECT_DOUBLE_EQ(points[0].imageWrongPct, 0.1);
}

TEST(ExplorerErrorPanel, AxisIsLinearFromZeroForNarrowRangesAndLogForWideOnes) {
  const sl::ChartAxis linear = sl::chooseChartAxis(2.0, 7.3, 0.01);
  EXPECT_FALSE(linear.log);
  EXPECT_DOUBLE_EQ(linear.lo, 0.0);
  EXPECT_GE(linear.hi, 7.3);
  EXPECT_LE(linear.hi, 10.0);
  EXPECT_DOUBLE_EQ(linear.toUnit(0.0), 0.0);
  EXPECT_DOUBLE_EQ(linear.toUnit(linear.hi), 1.0);
  EXPECT_GE(linear.ticks().size(), 3u);
  for (double t : linear.ticks()) {
    EXPECT_GE(t, linear.lo);
    EXPECT_LE(t, linear.hi);
  }

  const sl::ChartAxis log = sl::chooseChartAxis(0.05, 30.0, 0.01);
  EXPECT_TRUE(log.log);
  EXPECT_DOUBLE_EQ(log.lo, 0.01);
  EXPECT_DOUBLE_EQ(log.hi, 100.0);
  EXPECT_NEAR(log.toUnit(1.0), 0.5, 1e-9);
  EXPECT_DOUBLE_EQ(log.toUnit(0.0), 0.0);  // zero error sits on the floor, not at -infinity
  const std::vector<double> ticks = log.ticks();
  EXPECT_EQ(ticks.front(), 0.01);
  EXPECT_EQ(ticks.back(), 100.0);

  // No points: still a usable axis.
  const sl::ChartAxis empty = sl::chooseChartAxis(1e30, -1e30, 0.01);
  EXPECT_LT(empty.lo, empty.hi);
}

TEST(ExplorerErrorPanel, ViewportCostIsItsOwnPassesOnly) {
  const std::vector<sl::PassTiming> passes = {
      {"gbuffer", 1.0},         {"shadowmap[0]", 0.5},  {"shade[0]", 0.25},
      {"shadowmap[1]", 2.0},    {"visibility[1]", 1.0}, {"pixel-correct[1]", 0.5},
      {"view.history[1]", 9.0}, {"shade[1]", 0.25},     {"shadowmap[10]", 7.0}};
  const sl::ViewportCost a = sl::viewportFrameMs(passes, 0);
  EXPECT_DOUBLE_EQ(a.ownMs, 0.75);                            // the shared G-buffer is not in it
  EXPECT_DOUBLE_EQ(a.gbufferMs, 1.0);                         // but reported beside it
  const sl::ViewportCost b = sl::viewportFrameMs(passes, 1);  // debug views excluded
  EXPECT_DOUBLE_EQ(b.ownMs, 3.75);
  EXPECT_DOUBLE_EQ(sl::viewportFrameMs(passes, 10).ownMs, 7.0);
  EXPECT_LT(sl::viewportFrameMs(passes, 2).ownMs, 0.0);  // not rendered / not timed
  // Showing a debug view (its pass and the G-buffer it reads) does not change the cost.
  const std::vector<sl::PassTiming> plain = {{"shadowmap[0]", 0.5}, {"shade[0]", 0.25}};
  EXPECT_DOUBLE_EQ(sl::viewportFrameMs(plain, 0).ownMs, a.ownMs);
}

TEST(ExplorerErrorPanel, CostColumnIsTheMedianOfTheLast30Frames) {
  sl::MedianWindow w(sl::kCostFrames);
  ASSERT_EQ(sl::kCostFrames, 30u);
  // 20 frames at 2 ms and 10 slow ones (a hitch, another program): still 2, not the last reading.
  for (int i = 0; i < 20; ++i) w.add(2.0);
  for (int i = 0; i < 10; ++i) w.add(8.0);
  EXPECT_EQ(w.count(), 30u);
  EXPECT_DOUBLE_EQ(w.median(), 2.0);
  // Once most of the last 30 frames are slow, so is the median: the cost really changed.
  for (int i = 0; i < 6; ++i) w.add(8.0);
  EXPECT_EQ(w.count(), 30u);
  EXPECT_DOUBLE_EQ(w.median(), 8.0);
}

TEST(ExplorerErrorPanel, ConfigurationNamesTheChangedParameters) {
  sl::Technique t = sl::makeTechnique("standard");
  EXPECT_EQ(sl::configString(t), t.label());
  const std::string key = t.params.decls().front().key;
  const sl::ParamDecl& d = t.params.decls().front();
  const double other = d.type == sl::ParamType::Bool ? 1.0 - t.params.get(key)
                       : t.params.get(key) == d.max  ? d.min
                                                     : d.max;
  t.params.set(key, other);
  const std::string config = sl::configString(t);
  EXPECT_NE(config, t.label());
  EXPECT_NE(config.find(key + "="), std::string::npos) << config;
}

TEST(ExplorerErrorPanel, MedianIgnoresASpike) {
  sl::MedianWindow w(5);
  EXPECT_LT(w.median(), 0.0);
  for (double v : {1.0, 1.1, 250.0, 0.9, 1.0}) w.add(v);
  EXPECT_DOUBLE_EQ(w.median(), 1.0);
  for (int i = 0; i < 10; ++i) w.add(2.0);
  EXPECT_EQ(w.count(), 5u);
  EXPECT_DOUBLE_EQ(w.median(), 2.0);
}

// A scene of several lights: the accuracy CSV has a row per other shadowed light, named by the
// viewport and the light's number in the Scene section, with that light's own metrics and no
// image column (the colour sums every light and sits on the viewport's row).
TEST(ExplorerErrorPanel, OtherLightsGetARowEachWithTheirOwnMetrics) {
  std::vector<sl::LightVisibilityError> lights(3);
  lights[0] = {true, sl::ErrorMetrics{}};
  lights[0].error.wrongPixelPct = 1.25;
  lights[0].error.falseShadowPct = 1.0;
  lights[0].error.falseLightPct = 0.25;
  lights[2] = {true, sl::ErrorMetrics{}};
  lights[2].error.wrongPixelPct = 0.5;
  const std::string csv = sl::otherLightsCsvRows(2, "cube, shadowmap.size=512", lights);
  EXPECT_EQ(csv,
            "2 light 2,\"cube, shadowmap.size=512\",1.25,,1,0.25,0,0,\n"
            "2 light 4,\"cube, shadowmap.size=512\",0.5,,0,0,0,0,\n")
      << csv;
  EXPECT_EQ(sl::otherLightsCsvRows(1, "cube", {sl::LightVisibilityError{}}), "") << "an unshadowed light has no row";
}
