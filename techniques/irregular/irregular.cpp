// The irregular z-buffer as a representation: its state adds the list and triangle passes after
// the shadow pass, and its module reads the per-pixel result (techniques/irregular/README.md).
#include "irregular/irregular.h"

#include "irregular/izb_state.h"

namespace sl {

namespace {

class IrregularRepresentation : public Representation {
 public:
  std::string id() const override { return "irregular"; }
  std::string help() const override {
    return "irregular z-buffer (Johnson et al. 2004, Aila & Laine 2004; GPU lists as Sintorn et al. 2008): every "
           "visible eye sample binned in a light-space grid and tested exactly against each caster triangle. Debug "
           "view "
           "izb-lists: the grid, each cell by its list length (log scale: black empty, blue 1 sample, green 8, yellow "
           "~24, red >= 64; white = lost samples to the capacity)";
  }
  std::string glslModule() const override { return "representations/irregular.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {{.key = "izb.grid",
             .type = ParamType::Int,
             .min = 16,
             .max = 4096,
             .defaultValue = 512,
             .unit = "cells",
             .help = "cells per side of the light-space grid the eye samples are listed in (only speed depends on "
                     "it: few cells = long lists per triangle, many = more cells per triangle)",
             .logScale = true},
            {.key = "izb.capacity",
             .type = ParamType::Float,
             .min = 0.01,
             .max = 100,
             .defaultValue = 100,
             .unit = "% of pixels",
             .help = "entries of the sample-list buffer; samples past it overflow (counted in the status) and take "
                     "the shadow-map test instead",
             .logScale = true}};
  }
  std::unique_ptr<RepresentationState> createState() const override { return std::make_unique<IzbState>(); }
};

}  // namespace

void registerIrregularRepresentations(std::vector<std::unique_ptr<Representation>>& out) {
  out.push_back(std::make_unique<IrregularRepresentation>());
}

void addIrregularPresets(std::vector<Preset>& out) {
  out.push_back({"alias-free",
                 "irregular z-buffer (Johnson et al. 2004, Aila & Laine 2004, Sintorn et al. 2008): exact hard "
                 "shadows of every visible pixel, ray-traced-reference quality; samples listed in LiSPSM's light-space "
                 "grid (more cells near the viewer, where the samples are dense); a small map is kept for overflow",
                 "lispsm",
                 "irregular",
                 "none",
                 {"shadowmap.size=512"}});
  out.push_back({"alias-free-pixel-correct",
                 "the irregular z-buffer under pixel-correct accumulation: exact from the first frame, so the history "
                 "only repeats it",
                 "lispsm",
                 "irregular",
                 "pixel-correct",
                 {"shadowmap.size=512"}});
}

}  // namespace sl
