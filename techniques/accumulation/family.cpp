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

// The pixel-correct state's views (confidence, history, disocclusion).
void addPixelCorrectViewKeys(std::map<std::string, ColourKey>& keys) {
  // shaders/accumulation/views_confidence.frag.
  keys["confidence"] = {"shadow-test confidence (1 at a texel centre, or where the test is exact)",
                        "",
                        {{0.0f, {0.0f, 0.0f, 0.0f}, "0"}, {1.0f, {0.7f, 0.7f, 0.7f}, "1"}},
                        {{{1.0f, 0.55f, 0.0f}, "orange: update weight conf^m"}, kBlackNoGeometry},
                        "averaged over a pixel where texels are smaller than pixels"};
  keys["history"] = {"reprojected history s(n-1)",
                     "",
                     {{0.0f, {0.1f, 0.1f, 0.1f}, "0 shadow"}, {1.0f, {0.95f, 0.95f, 0.95f}, "1 lit"}},
                     {{{0.15f, 0.35f, 0.95f}, "blue: no history (cut, off-screen)"},
                      {{0.95f, 0.85f, 0.10f}, "yellow: replaced (moving caster)"},
                      kBlackNoGeometry},
                     ""};
  keys["disocclusion"] = {"why a pixel has no usable history",
                          "",
                          {},
                          {{{0.35f, 0.35f, 0.35f}, "grey: history used"},
                           {{0.6f, 0.2f, 0.8f}, "purple: none (after a cut)"},
                           {{0.15f, 0.35f, 0.95f}, "blue: off-screen last frame"},
                           {{1.0f, 0.5f, 0.0f}, "orange: disoccluded"},
                           {{0.95f, 0.85f, 0.1f}, "yellow: rejected (pc.reject)"},
                           kBlackNoGeometry},
                          ""};
}

}  // namespace

Family accumulationFamily() {
  Family f{.id = "accumulation",
           .summary =
               "what happens in screen space over time: none, or the pixel-correct confidence-weighted history "
               "(Scherzer et al. 2007)"};
  registerAccumulations(f.accumulations);
  addPixelCorrectPresets(f.presets);
  addPixelCorrectViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
