// Cube layout for a point light (techniques/point/cube_layout.cpp): six 90-degree perspective
// views from the light, one layer each, every one cropped to what the camera sees through it.
// A point reads the face whose axis is nearest its direction from the light (the largest
// distance along a face axis), so each point has exactly one face and no blend.
#define SL_LAYOUT_PICKS_VIEW
#include "layouts/single_matrix.glsl"

// Distance of worldPos along view `face`'s axis (its view-space -z).
float cubeAxisDistance(vec3 worldPos, int face) {
  mat4 m = lightViewMatrix[face];
  return -(m[0][2] * worldPos.x + m[1][2] * worldPos.y + m[2][2] * worldPos.z + m[3][2]);
}

int cubeFace(vec3 worldPos) {
  int face = 0;
  float best = cubeAxisDistance(worldPos, 0);
  for (int f = 1; f < 6; ++f) {
    float d = cubeAxisDistance(worldPos, f);
    if (d > best) {  // NaN never wins: a NaN point stays on face 0 and fails its w test
      best = d;
      face = f;
    }
  }
  return face;
}

ShadowCoord layoutShadowCoord(vec3 worldPos) {
  // Under a directional or spot light the layout gives one focused view.
  if (lightViewInfo.x < 5.5) return layoutShadowCoordIn(worldPos, 0);
  return layoutShadowCoordIn(worldPos, cubeFace(worldPos));
}
