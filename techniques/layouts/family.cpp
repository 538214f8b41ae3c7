// The layouts family's manifest: its parts and presets (registry.cpp lists the families).
#include "layouts/cascaded.h"
#include "layouts/face_partitioned.h"
#include "layouts/layouts.h"
#include "layouts/lispsm.h"
#include "layouts/logpsm.h"
#include "layouts/psm.h"
#include "layouts/tsm.h"
#include "part/family.h"

namespace sl {

namespace {

// Warping and partitioning layouts with the nearest test, and pixel-correct over cascades.
void addWarpingPresets(std::vector<Preset>& v) {
  v.insert(
      v.end(),
      {
          {"psm",
           "perspective shadow map (Stamminger & Drettakis 2002): post-perspective space, virtual camera slid back, "
           "nearest depth test",
           "psm",
           "depth-nearest",
           "none",
           {}},
          {"logpsm",
           "logarithmic warp along the view (after Lloyd et al. 2008), casters tessellated within an error budget, "
           "nearest depth test",
           "logpsm",
           "depth-nearest",
           "none",
           {}},
          {"tsm",
           "trapezoidal shadow map (Martin & Tan 2004): trapezoid around the view frustum to the square map, 80 % "
           "rule, "
           "nearest depth test",
           "tsm",
           "depth-nearest",
           "none",
           {}},
          {"cascaded",
           "cascaded / parallel-split shadow maps (Zhang et al. 2006, Engel 2007): 4 snapped splits of shadowmap.size² "
           "each, practical split scheme, blended borders, nearest depth test",
           "cascaded",
           "depth-nearest",
           "none",
           {}},
          {"pixel-correct-cascaded",
           "pixel-correct over cascades: jitter and confidence in each split's own texels",
           "cascaded",
           "depth-nearest",
           "pixel-correct",
           {}},
          {"face-partitioned",
           "face partitioning (Lloyd et al. 2006): one LiSPSM map per side face of the view frustum, nearest depth "
           "test",
           "face-partitioned",
           "depth-nearest",
           "none",
           // Measured: its warped maps' texels are anisotropic, and the slope bias measures the smaller
           // side; one texel of slope leaves acne near the horizon (techniques/layouts/README.md).
           {"bias.slope=2"}},
          {"sdsm",
           "sample-distribution shadow maps (Lauritzen et al. 2011): cascades split over the visible depth range from "
           "a GPU reduction (one frame of latency), nearest depth test",
           "cascaded",
           "depth-nearest",
           "none",
           {"fit.sdsm=on"}},
      });
}

// The partitioned layouts' view (cascaded, face-partitioned): which light view a pixel reads, in
// the colours of shaders/views/cascades.frag (the light-space overview draws the views' boxes in
// the same ones).
void addPartitionViewKeys(std::map<std::string, ColourKey>& keys) {
  keys["cascades"] = {"which light view (split) a pixel reads",
                      "",
                      {},
                      {{{0.90f, 0.30f, 0.25f}, "split 1"},
                       {{0.95f, 0.75f, 0.20f}, "split 2"},
                       {{0.35f, 0.75f, 0.30f}, "split 3"},
                       {{0.25f, 0.55f, 0.90f}, "split 4"},
                       {{0.65f, 0.40f, 0.85f}, "split 5+"}},
                      "mixed, hatched: blend band"};
}

}  // namespace

Family layoutsFamily() {
  Family f{.id = "layouts",
           .summary =
               "where the texels go: fitting, warping (PSM, LiSPSM, TSM, LogPSM) and partitioning (cascades, SDSM, "
               "face partitioning)"};
  registerBasicLayouts(f.layouts);
  registerWarpedLayouts(f.layouts);
  registerLogLayouts(f.layouts);
  registerCascadedLayouts(f.layouts);
  registerTrapezoidalLayouts(f.layouts);
  registerPerspectiveLayouts(f.layouts);
  registerFacePartitionedLayouts(f.layouts);
  addWarpingPresets(f.presets);
  addPartitionViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
