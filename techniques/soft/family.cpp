// The soft family's manifest: its parts and presets (registry.cpp lists the families).
#include "soft/pcss.h"
#include "part/family.h"
#include "part/penumbra_params.h"

namespace sl {

Family softFamily() {
  Family f{
      .id = "soft",
      .summary = "soft shadows from area lights: PCSS (Fernando 2005) and its pre-filtered and pixel-correct variants"};
  registerSoftRepresentations(f.representations);
  addSoftPresets(f.presets);
  addPenumbraViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
