// Cascaded / parallel-split layout (techniques/layouts/cascaded.cpp): view i serves camera view
// depths up to lightViewSplit[i].y; in the band of width lightViewSplit[i].z before that border
// the next view's test is blended in, so the step in texel density does not show as a seam.
#define SL_LAYOUT_PICKS_VIEW
#include "layouts/single_matrix.glsl"
uniform mat4 u_cameraView;

ShadowCoord layoutShadowCoord(vec3 worldPos) {
  float depth = -(u_cameraView * vec4(worldPos, 1.0)).z;
  int count = int(lightViewInfo.x + 0.5);
  int view = count - 1;
  for (int i = 0; i < count; ++i) {
    if (depth < lightViewSplit[i].y) {
      view = i;
      break;
    }
  }
  // A point on a split's rim (rounding, or a receiver outside the camera frustum: the overview)
  // goes to the first later split that holds it.
  // A do-while: llvmpipe runs a loop's body once even when every lane skips it, so the first
  // lookup is the body.
  ShadowCoord sc;
  --view;
  do {
    sc = layoutShadowCoordIn(worldPos, ++view);
  } while (!shadowCoordOnMap(sc) && view + 1 < count);
  float band = lightViewSplit[view].z;
  if (view + 1 < count && band > 0.0) {
    float w = (depth - (lightViewSplit[view].y - band)) / band;
    // Written so that a NaN depth gives no blend: NaN fails the comparison.
    if (w > 0.0 && shadowCoordOnMap(layoutShadowCoordIn(worldPos, view + 1))) {
      sc.view2 = view + 1;
      sc.weight2 = min(w, 1.0);
    }
  }
  return sc;
}
