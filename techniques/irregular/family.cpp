// The irregular family's manifest: its parts and presets (registry.cpp lists the families).
#include "irregular/irregular.h"
#include "part/family.h"

namespace sl {

namespace {

// The irregular z-buffer's view: how long each light-space cell's list of eye samples is.
void addIrregularViewKeys(std::map<std::string, ColourKey>& keys) {
  // shaders/views/izb_lists.frag (heat())
  keys["izb-lists"] = {"samples in each light-space cell's list (log scale)",
                       "samples",
                       {{0.0f, {0.0f, 0.0f, 1.0f}, "1 sample"},
                        {0.25f, {0.0f, 0.0f, 1.0f}, "2.8 samples"},
                        {0.5f, {0.0f, 1.0f, 0.0f}, "8 samples"},
                        {0.625f, {0.0f, 1.0f, 0.0f}, "13 samples"},
                        {0.75f, {0.5f, 1.0f, 0.0f}, "23 samples"},
                        {0.875f, {1.0f, 0.5f, 0.0f}, "38 samples"},
                        {1.0f, {1.0f, 0.0f, 0.0f}, "64+ samples"}},
                       {{{0.0f, 0.0f, 0.0f}, "black: empty cell (all black: layout gives no lists)"},
                        {{1.0f, 1.0f, 1.0f}, "white: list cut at the capacity (rest: shadow-map test)"}},
                       "the light's grid stretched over the view (x right, y up)"};
}

}  // namespace

Family irregularFamily() {
  Family f{.id = "irregular",
           .summary =
               "irregular z-buffer: exact hard shadows at every visible eye sample (Johnson et al. 2004, Sintorn et "
               "al. 2008)"};
  registerIrregularRepresentations(f.representations);
  addIrregularPresets(f.presets);
  addIrregularViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
