// The irregular family's manifest: its parts and presets (registry.cpp lists the families).
#include "irregular/irregular.h"
#include "part/family.h"

namespace sl {

Family irregularFamily() {
  Family f{.id = "irregular",
           .summary =
               "irregular z-buffer: exact hard shadows at every visible eye sample (Johnson et al. 2004, Sintorn et "
               "al. 2008)"};
  registerIrregularRepresentations(f.representations);
  addIrregularPresets(f.presets);
  return f;
}

}  // namespace sl
