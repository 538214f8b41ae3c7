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
  ShadowCoord sc = layoutShadowCoordIn(worldPos, view);
  // A point on a pyramid's border (rounding) may sit just outside its map: try the others.
  for (int i = 0; i < int(lightViewInfo.x + 0.5) && !(sc.view >= 0 && all(greaterThanEqual(sc.uv, vec2(0.0))) &&
                                                       all(lessThanEqual(sc.uv, vec2(1.0))));
       ++i)
    sc = layoutShadowCoordIn(worldPos, i);
  return sc;
}
