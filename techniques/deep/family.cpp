// The deep family's manifest: its parts and presets (registry.cpp lists the families).
#include "deep/deep_representation.h"
#include "part/family.h"

namespace sl {

Family deepFamily() {
  Family f{.id = "deep",
           .summary = "deep shadow maps: transmittance per light texel for hair and smoke (Lokovic & Veach 2000)"};
  registerDeepRepresentations(f.representations);
  addDeepPresets(f.presets);
  return f;
}

}  // namespace sl
