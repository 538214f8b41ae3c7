// One implementation of the error metrics, used by tests, `bench` and the explorer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sl {

struct ErrorMetrics {
  double wrongPixelPct = 0;   // |v - ref| > 30/255, percent of valid pixels
  double falseShadowPct = 0;  // v darker than ref by the threshold (dark where truth is lit)
  double falseLightPct = 0;   // v brighter than ref by the threshold (light leaks)
  double rmse = 0;            // of visibility over valid pixels
  long long validPixels = 0;
  long long nonfinite = 0;  // NaN/Inf in the technique's visibility (counted as wrong)
};

constexpr float kWrongThreshold = 30.0f / 255.0f;

// valid may be null (all pixels valid); else nonzero marks pixels covered by geometry.
ErrorMetrics compareVisibility(const float* technique, const float* reference, const uint8_t* valid, size_t count);

// The image-space figure of Scherzer et al. (figure 3): pixels of the final shaded image whose
// colour differs from the converged one, not pixels whose visibility does. A visibility error
// the shading hides (grazing light, dark albedo) is wrong in ErrorMetrics but not here.
struct ImageErrorMetrics {
  double imageWrongPct = 0;  // any of R, G, B differs by more than kImageWrongThreshold, % of valid pixels
  long long validPixels = 0;
};

constexpr int kImageWrongThreshold = 30;  // of 255, in 8-bit units: a difference of exactly 30 is not wrong

// Two RGBA8 images of `count` pixels (alpha ignored); valid as in compareVisibility.
ImageErrorMetrics compareImages(const uint8_t* technique, const uint8_t* reference, const uint8_t* valid, size_t count);

// Mean absolute frame-to-frame change of visibility over valid pixels, across a sequence.
double meanTemporalChange(const std::vector<std::vector<float>>& frames, const uint8_t* valid);

// Per pixel: mean absolute frame-to-frame change (0 where invalid or never finite twice in a row).
std::vector<float> temporalChangeMap(const std::vector<std::vector<float>>& frames, const uint8_t* valid);

// Flicker: per pixel, how much more the technique's value changed along the sequence than the
// truth's (clipped at 0), averaged over valid pixels; from temporalChangeMap of both. Per pixel so
// that one pixel's lag cannot cancel another's noise, and lag or blur (changes spread over more
// frames, or late) does not count: a pixel that flips once, like the truth, adds 0 whenever it
// flips; one that flips back and forth adds the extra changes.
double flickerExcess(const std::vector<float>& techniqueMap, const std::vector<float>& referenceMap,
                     const uint8_t* valid);

// Where a technique flickers more than the truth: RGBA8 from per-pixel mean changes of technique
// and reference. Black = invalid, grey = as stable as the reference, yellow to white = excess
// change (saturating at `fullScale`), blue = steadier than the reference.
std::vector<uint8_t> flickerImage(const std::vector<float>& technique, const std::vector<float>& reference,
                                  const uint8_t* valid, float fullScale);

// Error image for the `error` debug view: RGBA8, grey = agree, orange = false shadow,
// blue = false light (colours chosen to be told apart by colour-blind viewers too).
std::vector<uint8_t> errorImage(const float* technique, const float* reference, const uint8_t* valid, size_t count);

}  // namespace sl
