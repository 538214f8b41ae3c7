// The reconstruction family's manifest: its parts and presets (registry.cpp lists the families).
#include "reconstruction/reconstruction.h"
#include "part/family.h"

namespace sl {

Family reconstructionFamily() {
  Family f{.id = "reconstruction",
           .summary =
               "reconstruction beyond one depth per texel: silhouette maps (Sen et al. 2003) and forward shadow "
               "mapping (Zhang 1998)"};
  registerReconstructionRepresentations(f.representations);
  registerForwardAccumulation(f.accumulations);
  addReconstructionPresets(f.presets);
  return f;
}

}  // namespace sl
