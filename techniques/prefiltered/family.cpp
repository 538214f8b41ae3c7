// The prefiltered family's manifest: its parts and presets (registry.cpp lists the families).
#include "prefiltered/prefiltered_representations.h"
#include "part/family.h"

namespace sl {

Family prefilteredFamily() {
  Family f{
      .id = "prefiltered",
      .summary =
          "pre-filtered visibility: variance, exponential, moment, Gaussian and convolution (Fourier) shadow maps"};
  registerPrefilteredRepresentations(f.representations);
  addPrefilteredPresets(f.presets);
  return f;
}

}  // namespace sl
