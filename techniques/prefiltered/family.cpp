// The prefiltered family's manifest: its parts and presets (registry.cpp lists the families).
#include "prefiltered/prefiltered_representations.h"
#include "part/family.h"
#include "part/penumbra_params.h"

namespace sl {

namespace {

// The moment maps' views: a stored channel, the filtered variance and a Fourier basis image.
void addMomentViewKeys(std::map<std::string, ColourKey>& keys) {
  // shaders/views/moments.frag (no define: texelColor's unsigned branch), channel from
  // techniques/prefiltered/filter_params.cpp
  keys["moments"] = {"stored moment channel view.channel (fixed scale)",
                     "",
                     {{0.0f, {0.0f, 0.0f, 0.0f}, "<= 0"},
                      {0.25f, {0.5f, 0.5f, 0.5f}, "0.5"},
                      {0.5f, {1.0f, 1.0f, 1.0f}, "1"},
                      {0.75f, {1.0f, 0.9f, 0.55f}, "1e3"},
                      {1.0f, {1.0f, 0.8f, 0.1f}, ">= 1e6"}},
                     {{{1.0f, 0.0f, 1.0f}, "magenta: NaN/Inf"},
                      {{0.0f, 0.0f, 0.0f}, "black: value <= 0 (e.g. EVSM's negative warp)"},
                      {{0.08f, 0.08f, 0.10f}, "near-black: outside the layers' tiles"}},
                     "view.channel picks it: 0 depth (or warp), 1 its square; linear to 1, log above; texels "
                     "filter.skip_unread leaves (no visible receiver reads them) show an empty texel's"};
  // shaders/views/moments.frag (SL_VIEW_VARIANCE), representationVariance() of each module in
  // shaders/representations/prefiltered/
  keys["variance"] = {"variance of the filtered moments (log, fixed scale)",
                      "depth^2",
                      {{0.0f, {0.15f, 0.10f, 0.40f}, "1e-8 depth^2"},
                       {0.333f, {0.10f, 0.50f, 0.55f}, "2e-6 depth^2"},
                       {0.667f, {0.35f, 0.75f, 0.35f}, "5e-4 depth^2"},
                       {1.0f, {0.98f, 0.90f, 0.20f}, "0.1 depth^2"}},
                      {{{0.0f, 0.0f, 0.0f}, "black: variance <= 0 (flat box, empty map, texels the blur skipped)"},
                       {{1.0f, 1.0f, 1.0f}, "white: a notch per decade in the bottom key band"},
                       {{0.08f, 0.08f, 0.10f}, "near-black: outside the layers' tiles"}},
                      "over the filter.width box; EVSM/EWGF/LVSM: of the warped depth; tile per layer"};
  // shaders/views/moments.frag (SL_VIEW_SIGNED: signedColor()), basis from
  // shaders/representations/prefiltered/convolution_series.glsl
  keys["fourier"] = {
      "Fourier basis image view.channel (signed)",
      "",
      {{0.0f, {0.15f, 0.30f, 0.90f}, "-1"}, {0.5f, {0.95f, 0.95f, 0.95f}, "0"}, {1.0f, {0.90f, 0.20f, 0.10f}, "+1"}},
      {{{1.0f, 0.0f, 1.0f}, "magenta: NaN/Inf"}, {{0.08f, 0.08f, 0.10f}, "near-black: outside the layers' tiles"}},
      "view.channel 2k-2 = sin, 2k-1 = cos of term k, at (2k-1) pi 0.9z; clamped to +-1"};
}

}  // namespace

Family prefilteredFamily() {
  Family f{
      .id = "prefiltered",
      .summary =
          "pre-filtered visibility: variance, exponential, moment, Gaussian and convolution (Fourier) shadow maps"};
  registerPrefilteredRepresentations(f.representations);
  addPrefilteredPresets(f.presets);
  addMomentViewKeys(f.viewKeys);
  addPenumbraViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
