// Face partitioning (techniques/layouts/face_partitioned.cpp): the camera frustum is split by
// its two diagonal planes into four pyramids, one per side face (right, left, top, bottom); view i
// is the warped map of pyramid i (i + 4: its far slice, with faces.depth_splits = 2). A pixel
// picks its pyramid from its camera clip position and its slice from its view depth.
#define SL_LAYOUT_PICKS_VIEW
#include "layouts/single_matrix.glsl"
uniform mat4 u_cameraViewProj;

ShadowCoord layoutShadowCoord(vec3 worldPos) {
  vec4 c = u_cameraViewProj * vec4(worldPos, 1.0);
  vec2 q = c.xy;  // the sign of w is the same for every visible point: no division needed
  int view = abs(q.x) >= abs(q.y) ? (q.x >= 0.0 ? 0 : 1) : (q.y >= 0.0 ? 2 : 3);
  // Depth slices (faces.depth_splits): views 4..7 are the far slice; c.w is the view depth.
  if (int(lightViewInfo.x + 0.5) > 4 && c.w >= lightViewSplit[view].y) view += 4;
  view = min(view, int(lightViewInfo.x + 0.5) - 1);
  // The picked view holds the point up to rounding; one on a pyramid's border may sit just
  // outside its map: then the others are tried. A do-while: llvmpipe runs a loop's body once
  // even when every lane skips it, so the first lookup is the body (a for loop after it cost 18
  // ms of shading at 1280x720).
  int count = int(lightViewInfo.x + 0.5);
  ShadowCoord sc;
  int tried = 0;
  do {
    sc = layoutShadowCoordIn(worldPos, view);
    view = view + 1 == count ? 0 : view + 1;
  } while (!shadowCoordOnMap(sc) && ++tried < count);
  return sc;
}
