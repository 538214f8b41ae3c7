// Error metrics of a technique's visibility against the ray-traced reference.
// Definitions (see docs/reference.md): a pixel is wrong when |v - ref| > 30/255, the threshold
// of Scherzer, Jeschke, Wimmer, "Pixel-Correct Shadow Maps with Temporal Reprojection and
// Shadow Test Confidence", EGSR 2007, figure 3.
#include <cstddef>  // metrics.h uses size_t without including it

#include "metrics/metrics.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sl {

namespace {

bool isValid(const uint8_t* valid, size_t i) { return valid == nullptr || valid[i] != 0; }

}  // namespace

ErrorMetrics compareVisibility(const float* technique, const float* reference, const uint8_t* valid, size_t count) {
  ErrorMetrics m;
  if (count == 0) return m;
  if (!technique || !reference)
    throw std::invalid_argument("compareVisibility: technique and reference must not be null");

  // Differences are taken in double from the float inputs, so a difference of exactly
  // kWrongThreshold (e.g. ref 0, v 30/255f) compares as equal and is not wrong.
  const double threshold = static_cast<double>(kWrongThreshold);
  long long wrong = 0, falseShadow = 0, falseLight = 0, finiteCount = 0;
  double squaredSum = 0.0;
  for (size_t i = 0; i < count; ++i) {
    if (!isValid(valid, i)) continue;
    const double ref = reference[i];
    // A broken reference pixel says nothing about the technique: leave it out entirely.
    if (!std::isfinite(ref)) continue;
    ++m.validPixels;
    const double v = technique[i];
    if (!std::isfinite(v)) {
      // NaN/Inf is always wrong but has no direction (neither false shadow nor false light), and
      // is kept out of the rmse sums so one broken pixel cannot make the rmse NaN/Inf.
      ++m.nonfinite;
      ++wrong;
      continue;
    }
    const double diff = v - ref;
    squaredSum += diff * diff;
    ++finiteCount;
    if (diff < -threshold) {
      ++wrong;
      ++falseShadow;
    } else if (diff > threshold) {
      ++wrong;
      ++falseLight;
    }
  }
  if (m.validPixels > 0) {
    const double toPercent = 100.0 / static_cast<double>(m.validPixels);
    m.wrongPixelPct = wrong * toPercent;
    m.falseShadowPct = falseShadow * toPercent;
    m.falseLightPct = falseLight * toPercent;
  }
  if (finiteCount > 0) m.rmse = std::sqrt(squaredSum / static_cast<double>(finiteCount));
  return m;
}

ImageErrorMetrics compareImages(const uint8_t* technique, const uint8_t* reference, const uint8_t* valid,
                                size_t count) {
  ImageErrorMetrics m;
  if (count == 0) return m;
  if (!technique || !reference) throw std::invalid_argument("compareImages: technique and reference must not be null");
  long long wrong = 0;
  for (size_t i = 0; i < count; ++i) {
    if (!isValid(valid, i)) continue;
    ++m.validPixels;
    for (size_t c = 0; c < 3; ++c) {
      if (std::abs(int(technique[4 * i + c]) - int(reference[4 * i + c])) > kImageWrongThreshold) {
        ++wrong;
        break;
      }
    }
  }
  if (m.validPixels > 0) m.imageWrongPct = 100.0 * static_cast<double>(wrong) / static_cast<double>(m.validPixels);
  return m;
}

double meanTemporalChange(const std::vector<std::vector<float>>& frames, const uint8_t* valid) {
  if (frames.size() < 2) return 0.0;
  const size_t count = frames.front().size();
  for (const auto& frame : frames)
    if (frame.size() != count)
      throw std::invalid_argument("meanTemporalChange: all frames must have the same pixel count");

  // Averaged over every (pair of consecutive frames, valid pixel) where both values are finite.
  double sum = 0.0;
  long long samples = 0;
  for (size_t f = 1; f < frames.size(); ++f) {
    const std::vector<float>& previous = frames[f - 1];
    const std::vector<float>& current = frames[f];
    for (size_t i = 0; i < count; ++i) {
      if (!isValid(valid, i)) continue;
      const double a = previous[i];
      const double b = current[i];
      if (!std::isfinite(a) || !std::isfinite(b)) continue;
      sum += std::abs(b - a);
      ++samples;
    }
  }
  return samples > 0 ? sum / static_cast<double>(samples) : 0.0;
}

std::vector<float> temporalChangeMap(const std::vector<std::vector<float>>& frames, const uint8_t* valid) {
  const size_t count = frames.empty() ? 0 : frames.front().size();
  std::vector<float> map(count, 0.0f);
  std::vector<int> samples(count, 0);
  for (size_t f = 1; f < frames.size(); ++f) {
    if (frames[f].size() != count || frames[f - 1].size() != count)
      throw std::invalid_argument("temporalChangeMap: all frames must have the same pixel count");
    for (size_t i = 0; i < count; ++i) {
      const float a = frames[f - 1][i], b = frames[f][i];
      if (!isValid(valid, i) || !std::isfinite(a) || !std::isfinite(b)) continue;
      map[i] += std::abs(b - a);
      ++samples[i];
    }
  }
  for (size_t i = 0; i < count; ++i) map[i] = samples[i] > 0 ? map[i] / static_cast<float>(samples[i]) : 0.0f;
  return map;
}

double flickerExcess(const std::vector<float>& techniqueMap, const std::vector<float>& referenceMap,
                     const uint8_t* valid) {
  if (techniqueMap.size() != referenceMap.size())
    throw std::invalid_argument("flickerExcess: technique and reference maps differ in size");
  double sum = 0.0;
  long long pixels = 0;
  for (size_t i = 0; i < techniqueMap.size(); ++i) {
    if (!isValid(valid, i)) continue;
    sum += std::max(0.0, static_cast<double>(techniqueMap[i]) - referenceMap[i]);
    ++pixels;
  }
  return pixels > 0 ? sum / static_cast<double>(pixels) : 0.0;
}

std::vector<uint8_t> flickerImage(const std::vector<float>& technique, const std::vector<float>& reference,
                                  const uint8_t* valid, float fullScale) {
  if (technique.size() != reference.size())
    throw std::invalid_argument("flickerImage: technique and reference maps differ in size");
  if (!(fullScale > 0.0f)) throw std::invalid_argument("flickerImage: fullScale must be positive");
  std::vector<uint8_t> rgba(technique.size() * 4, 0);
  for (size_t i = 0; i < technique.size(); ++i) {
    rgba[4 * i + 3] = 255;
    if (!isValid(valid, i)) continue;
    const float excess = (technique[i] - reference[i]) / fullScale;
    auto byte = [](float x) { return static_cast<uint8_t>(std::lround(255.0f * std::clamp(x, 0.0f, 1.0f))); };
    if (excess > 0.0f) {  // grey -> yellow -> white as the excess grows
      rgba[4 * i + 0] = byte(0.35f + 0.65f * std::min(1.0f, 2.0f * excess));
      rgba[4 * i + 1] = byte(0.35f + 0.65f * std::min(1.0f, 2.0f * excess) * 0.85f + 0.15f * excess);
      rgba[4 * i + 2] = byte(0.35f * (1.0f - std::min(1.0f, 2.0f * excess)) + std::max(0.0f, 2.0f * excess - 1.0f));
    } else {  // grey -> blue where steadier than the truth (lagging or blurred edges)
      const float t = std::min(1.0f, -excess);
      rgba[4 * i + 0] = byte(0.35f * (1.0f - t));
      rgba[4 * i + 1] = byte(0.35f * (1.0f - t) + 0.45f * t);
      rgba[4 * i + 2] = byte(0.35f + 0.65f * t);
    }
  }
  return rgba;
}

std::vector<uint8_t> errorImage(const float* technique, const float* reference, const uint8_t* valid, size_t count) {
  std::vector<uint8_t> rgba(count * 4, 0);
  if (count == 0) return rgba;
  if (!technique || !reference) throw std::invalid_argument("errorImage: technique and reference must not be null");
  const double threshold = static_cast<double>(kWrongThreshold);
  auto put = [&](size_t i, uint8_t r, uint8_t g, uint8_t b) {
    rgba[4 * i + 0] = r;
    rgba[4 * i + 1] = g;
    rgba[4 * i + 2] = b;
    rgba[4 * i + 3] = 255;
  };
  for (size_t i = 0; i < count; ++i) {
    const double ref = reference[i];
    if (!isValid(valid, i) || !std::isfinite(ref)) {
      put(i, 0, 0, 0);  // background: black
      continue;
    }
    const double v = technique[i];
    if (!std::isfinite(v)) {
      put(i, 255, 0, 255);  // NaN/Inf: magenta, so broken output is never mistaken for an error sign
    } else if (v - ref < -threshold) {
      put(i, 230, 120, 0);  // false shadow: orange
    } else if (v - ref > threshold) {
      put(i, 40, 120, 255);  // false light: blue
    } else {
      // Agreeing pixels show the reference at half brightness, so the scene stays readable
      // while the error colours stand out.
      const double grey = 0.5 * std::clamp(ref, 0.0, 1.0) * 255.0;
      const auto g = static_cast<uint8_t>(std::lround(grey));
      put(i, g, g, g);
    }
  }
  return rgba;
}

}  // namespace sl
