// The accumulation family's manifest: its parts and presets (registry.cpp lists the families).
#include "part/family.h"

namespace sl {

void registerAccumulations(std::vector<std::unique_ptr<Accumulation>>& out);

namespace {

// The pixel-correct paper's presets (Scherzer et al. 2007) and the LiSPSM layout it pairs with.
void addPixelCorrectPresets(std::vector<Preset>& v) {
  v.insert(v.end(),
           {
               {"pixel-correct",
                "focused map, nearest test, confidence-weighted screen-space history (Scherzer et al. 2007)",
                "focused",
                "depth-nearest",
                "pixel-correct",
                {}},
               {"lispsm",
                "light space perspective shadow map (Wimmer et al. 2004), nearest depth test",
                "lispsm",
                "depth-nearest",
                "none",
                {}},
               {"pixel-correct-lispsm",
                "pixel-correct over a LiSPSM layout, as the paper pairs them",
                "lispsm",
                "depth-nearest",
                "pixel-correct",
                {}},
               {"pixel-correct-at-rest",
                "pixel-correct that shows the layout's plain test while the camera moves and keeps the most confident "
                "test at rest",
                "focused",
                "depth-nearest",
                "pixel-correct",
                {"pc.while_moving=test", "pc.keep_best=on"}},
               {"pixel-correct-pcf",
                "pixel-correct with 3x3 PCF tests as f(n): smoother edges while converging",
                "focused",
                "depth-pcf",
                "pixel-correct",
                {"pcf.kernel=3"}},
           });
}

}  // namespace

Family accumulationFamily() {
  Family f{.id = "accumulation",
           .summary =
               "what happens in screen space over time: none, or the pixel-correct confidence-weighted history "
               "(Scherzer et al. 2007)"};
  registerAccumulations(f.accumulations);
  addPixelCorrectPresets(f.presets);
  return f;
}

}  // namespace sl
