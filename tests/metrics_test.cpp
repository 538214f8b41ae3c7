// Error metrics on small synthetic images whose answers are known by construction.
#include <cstddef>  // metrics.h uses size_t without including it

#include "metrics/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace sl {
namespace {

TEST(Metrics, IdenticalImagesHaveNoError) {
  const std::vector<float> ref = {0.0f, 0.25f, 0.5f, 1.0f};
  const ErrorMetrics m = compareVisibility(ref.data(), ref.data(), nullptr, ref.size());
  EXPECT_EQ(m.validPixels, 4);
  EXPECT_DOUBLE_EQ(m.wrongPixelPct, 0.0);
  EXPECT_DOUBLE_EQ(m.falseShadowPct, 0.0);
  EXPECT_DOUBLE_EQ(m.falseLightPct, 0.0);
  EXPECT_DOUBLE_EQ(m.rmse, 0.0);
  EXPECT_EQ(m.nonfinite, 0);
}

TEST(Metrics, ExactPercentagesAndFalseShadowLightSplit) {
  // 8 pixels: 2 false shadows (dark where lit), 1 false light, 1 small difference, 4 equal.
  const std::vector<float> ref = {1, 1, 0, 1, 0, 0, 1, 0.5f};
  const std::vector<float> tech = {0, 0, 1, 1, 0, 0, 1, 0.55f};
  const ErrorMetrics m = compareVisibility(tech.data(), ref.data(), nullptr, ref.size());
  EXPECT_EQ(m.validPixels, 8);
  EXPECT_DOUBLE_EQ(m.wrongPixelPct, 3.0 / 8.0 * 100.0);
  EXPECT_DOUBLE_EQ(m.falseShadowPct, 2.0 / 8.0 * 100.0);
  EXPECT_DOUBLE_EQ(m.falseLightPct, 1.0 / 8.0 * 100.0);
  const double d = static_cast<double>(0.55f) - static_cast<double>(0.5f);
  EXPECT_NEAR(m.rmse, std::sqrt((3.0 + d * d) / 8.0), 1e-12);
}

TEST(Metrics, ValidMaskIsRespected) {
  const std::vector<float> ref = {1, 1, 1, 1};
  const std::vector<float> tech = {0, 0, 1, 0};
  const std::vector<uint8_t> valid = {1, 0, 1, 0};  // only pixels 0 and 2 count
  const ErrorMetrics m = compareVisibility(tech.data(), ref.data(), valid.data(), ref.size());
  EXPECT_EQ(m.validPixels, 2);
  EXPECT_DOUBLE_EQ(m.wrongPixelPct, 50.0);
  EXPECT_DOUBLE_EQ(m.falseShadowPct, 50.0);
  EXPECT_DOUBLE_EQ(m.falseLightPct, 0.0);
  EXPECT_NEAR(m.rmse, std::sqrt(0.5), 1e-12);
}

TEST(Metrics, NoValidPixelsGivesZeros) {
  const std::vector<float> ref = {1, 0};
  const std::vector<float> tech = {0, 1};
  const std::vector<uint8_t> valid = {0, 0};
  const ErrorMetrics m = compareVisibility(tech.data(), ref.data(), valid.data(), ref.size());
  EXPECT_EQ(m.validPixels, 0);
  EXPECT_DOUBLE_EQ(m.wrongPixelPct, 0.0);
  EXPECT_DOUBLE_EQ(m.rmse, 0.0);
}

TEST(Metrics, NonFiniteCountsAsWrongButKeepsRmseFinite) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> ref = {1, 1, 0, 0};
  const std::vector<float> tech = {nan, inf, 1, 0};
  const ErrorMetrics m = compareVisibility(tech.data(), ref.data(), nullptr, ref.size());
  EXPECT_EQ(m.validPixels, 4);
  EXPECT_EQ(m.nonfinite, 2);
  EXPECT_DOUBLE_EQ(m.wrongPixelPct, 75.0);  // two non-finite + one false light
  EXPECT_DOUBLE_EQ(m.falseLightPct, 25.0);
  EXPECT_DOUBLE_EQ(m.falseShadowPct, 0.0);  // non-finite pixels have no direction
  ASSERT_TRUE(std::isfinite(m.rmse));
  EXPECT_NEAR(m.rmse, std::sqrt(1.0 / 2.0), 1e-12);  // over the two finite pixels
}

TEST(Metrics, ThresholdBoundary) {
  // A difference of exactly 30/255 is not wrong; the next float above it is.
  const float above = std::nextafter(kWrongThreshold, 1.0f);
  // Pixel 0: +30/255 exactly, pixel 1: just above (false light), pixel 2: -30/255 exactly,
  // pixel 3: just below -30/255 (false shadow).
  const std::vector<float> ref2 = {0, 0, kWrongThreshold, above};
  const std::vector<float> tech = {kWrongThreshold, above, 0.0f, 0.0f};
  const ErrorMetrics m = compareVisibility(tech.data(), ref2.data(), nullptr, ref2.size());
  EXPECT_EQ(m.validPixels, 4);
  EXPECT_DOUBLE_EQ(m.wrongPixelPct, 50.0);
  EXPECT_DOUBLE_EQ(m.falseLightPct, 25.0);   // pixel 1
  EXPECT_DOUBLE_EQ(m.falseShadowPct, 25.0);  // pixel 3
}

TEST(Metrics, ImageWrongThresholdIsThirtyOf255PerChannel) {
  // Reference pixels, then the technique's: equal; R +30 (not wrong); G -31 (wrong); B +31
  // (wrong); every channel +30 (not wrong: the threshold is per channel, not summed); alpha
  // only (ignored); R -30 and B +31 (wrong once, not twice).
  const std::vector<uint8_t> ref = {100, 100, 100, 255, 100, 100, 100, 255, 100, 100, 100, 255, 100, 100,
                                    100, 255, 100, 100, 100, 255, 100, 100, 100, 255, 100, 100, 100, 255};
  const std::vector<uint8_t> tech = {100, 100, 100, 255, 130, 100, 100, 255, 100, 69, 100, 255, 100, 100,
                                     131, 255, 130, 130, 130, 255, 100, 100, 100, 0,  70,  100, 131, 255};
  const size_t n = ref.size() / 4;
  const ImageErrorMetrics m = compareImages(tech.data(), ref.data(), nullptr, n);
  EXPECT_EQ(m.validPixels, 7);
  EXPECT_DOUBLE_EQ(m.imageWrongPct, 3.0 / 7.0 * 100.0);
  // The same both ways round, and at the ends of the range.
  EXPECT_DOUBLE_EQ(compareImages(ref.data(), tech.data(), nullptr, n).imageWrongPct, m.imageWrongPct);
  const std::vector<uint8_t> black = {0, 0, 0, 255, 0, 0, 0, 255}, ends = {30, 0, 0, 255, 0, 0, 31, 255};
  EXPECT_DOUBLE_EQ(compareImages(ends.data(), black.data(), nullptr, 2).imageWrongPct, 50.0);
  // Only valid pixels count: pixels 2 and 3 (both wrong) left out.
  const std::vector<uint8_t> valid = {1, 1, 0, 0, 1, 1, 1};
  const ImageErrorMetrics v = compareImages(tech.data(), ref.data(), valid.data(), n);
  EXPECT_EQ(v.validPixels, 5);
  EXPECT_DOUBLE_EQ(v.imageWrongPct, 1.0 / 5.0 * 100.0);
  const std::vector<uint8_t> none(n, 0);
  EXPECT_DOUBLE_EQ(compareImages(tech.data(), ref.data(), none.data(), n).imageWrongPct, 0.0);
}

TEST(Metrics, MeanTemporalChange) {
  const std::vector<std::vector<float>> frames = {{0, 1, 0}, {1, 1, 0}, {1, 0, 0.5f}};
  // Pairs: |1-0|+|1-1|+|0-0| = 1 and |0|+|0-1|+|0.5| = 1.5 over 6 samples.
  EXPECT_NEAR(meanTemporalChange(frames, nullptr), 2.5 / 6.0, 1e-12);
  const std::vector<uint8_t> valid = {1, 0, 0};  // only pixel 0: changes 1 and 0
  EXPECT_NEAR(meanTemporalChange(frames, valid.data()), 0.5, 1e-12);
  EXPECT_DOUBLE_EQ(meanTemporalChange({{1, 0}}, nullptr), 0.0);
  EXPECT_THROW(meanTemporalChange({{1, 0}, {1}}, nullptr), std::invalid_argument);
}

TEST(Metrics, FlickerExcessCountsExtraChangesNotLag) {
  // Truth: pixel 0 flips once (frame 1), pixel 1 steady, pixel 2 flips once (frame 2).
  const std::vector<std::vector<float>> truth = {{0, 1, 0}, {1, 1, 0}, {1, 1, 1}, {1, 1, 1}};
  const auto ref = temporalChangeMap(truth, nullptr);
  EXPECT_NEAR(ref[0], 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(ref[1], 0.0, 1e-6);
  // Late (pixel 0 flips a frame later) and blurred (pixel 2 in two half steps): no flicker.
  const std::vector<std::vector<float>> lagging = {{0, 1, 0}, {0, 1, 0}, {1, 1, 0.5f}, {1, 1, 1}};
  EXPECT_NEAR(flickerExcess(temporalChangeMap(lagging, nullptr), ref, nullptr), 0.0, 1e-9);
  // Pixel 1 goes dark and back (2 changes the truth does not have), the rest as the truth:
  // 2/3 per frame pair on one of three pixels. The lag elsewhere does not cancel it.
  const std::vector<std::vector<float>> flickering = {{0, 1, 0}, {0, 0, 0}, {1, 1, 0.5f}, {1, 1, 1}};
  EXPECT_NEAR(flickerExcess(temporalChangeMap(flickering, nullptr), ref, nullptr), (2.0 / 3.0) / 3.0, 1e-6);
  const std::vector<uint8_t> valid = {1, 0, 1};  // the flickering pixel excluded
  EXPECT_NEAR(flickerExcess(temporalChangeMap(flickering, nullptr), ref, valid.data()), 0.0, 1e-9);
  EXPECT_THROW(flickerExcess({0.0f}, {0.0f, 1.0f}, nullptr), std::invalid_argument);
}

TEST(Metrics, ErrorImageColours) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<float> ref = {1, 1, 0, 1, 1};
  const std::vector<float> tech = {1, 0, 1, 1, nan};
  const std::vector<uint8_t> valid = {1, 1, 1, 0, 1};
  const std::vector<uint8_t> img = errorImage(tech.data(), ref.data(), valid.data(), ref.size());
  ASSERT_EQ(img.size(), 20u);
  auto pixel = [&](int i) { return std::vector<int>{img[4 * i], img[4 * i + 1], img[4 * i + 2], img[4 * i + 3]}; };
  EXPECT_EQ(pixel(0), (std::vector<int>{128, 128, 128, 255}));  // agree: half the reference
  EXPECT_EQ(pixel(1), (std::vector<int>{230, 120, 0, 255}));    // false shadow: orange
  EXPECT_EQ(pixel(2), (std::vector<int>{40, 120, 255, 255}));   // false light: blue
  EXPECT_EQ(pixel(3), (std::vector<int>{0, 0, 0, 255}));        // invalid: black
  EXPECT_EQ(pixel(4), (std::vector<int>{255, 0, 255, 255}));    // non-finite: magenta
}

}  // namespace
}  // namespace sl
