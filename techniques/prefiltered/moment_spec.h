// What a pre-filtered representation stores per texel, as its state needs to know it: how many
// floats, their value where nothing was drawn (the moments of depth 1), whether they are
// filtered in log space, and the compile-time defines its GLSL module reads.
#pragma once

#include "core/params.h"

#include <functional>
#include <string>
#include <vector>

namespace sl {

struct MomentSpec {
  // Stored floats per texel (1..32): one target holds up to four, more use several targets.
  std::function<int(const ParamSet&)> channels;
  // The representation's moments of depth 1 (the far plane): what a texel holds where no caster
  // was drawn. Mirrors representationMoments(1.0) in GLSL (tests compare the two).
  std::function<std::vector<float>(const ParamSet&)> clearValue;
  // Extra defines for the GLSL module (terms, exponent clamps).
  std::function<std::string(const ParamSet&)> defines;
  // ESM: the stored value is depth, filtered as log(sum w exp(c z)) / c, so that no exponential
  // of a large c z is ever stored or summed (it would overflow 16-bit and even 32-bit floats).
  bool logFilter = false;
  std::string logExponentKey;  // the parameter holding c
  // Debug views: the GLSL module defines representationVariance; the channels are Fourier basis
  // images (signed).
  bool hasVariance = false;
  bool fourier = false;
  // Non-empty: a soft representation of that name (prefiltered/soft_moments.glsl), which sizes
  // its box per pixel from the area light and so always filters by summed-area table (32-bit),
  // with no filter.method / filter.width of its own.
  std::string softName;
  bool soft() const { return !softName.empty(); }
  // The soft ones: how many of the first channels the reconstruction under a point of light
  // reads (CSM-Z: the basis, not the basis times depth its blocker estimate needs); empty: all.
  std::function<int(const ParamSet&)> pointLightChannels;
};

// Parameters every pre-filtered representation has (storage format, filter method and width).
// withSat: summed-area tables are offered (not for ESM, whose log-space average is no sum).
std::vector<ParamDecl> filterParams(bool withSat);
// What the soft ones have of those: the channel their debug views show.
std::vector<ParamDecl> softFilterParams();
// Bits per stored float of the `filter.format` parameter: 16 or 32.
int formatBits(const ParamSet& params);
// The largest exponent c for which exp(c)^2 stays finite in the storage format: what EVSM's
// squared moments need (fp16: 65504 = e^11.09, so 5.54; fp32: e^88.7, so 44; 42 leaves headroom
// for the blur's sums).
float maxWarpExponent(int bits);

}  // namespace sl
