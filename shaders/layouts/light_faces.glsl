// Face layouts for a point light (techniques/point/light_faces.cpp): the cube's six faces and the
// tetrahedron's four, perspective views from the light, one layer each, every one cropped to what
// the camera sees through it. A point reads the face whose axis is nearest its direction from the
// light (the largest distance along a face axis), so each point has exactly one face and no blend.
#define SL_LAYOUT_PICKS_VIEW
#include "layouts/single_matrix.glsl"

// Distance of worldPos along view `face`'s axis (its view-space -z).
float faceAxisDistance(vec3 worldPos, int face) {
  mat4 m = lightViewMatrix[face];
  return -(m[0][2] * worldPos.x + m[1][2] * worldPos.y + m[2][2] * worldPos.z + m[3][2]);
}

int nearestFace(vec3 worldPos, int count) {
  int face = 0;
  float best = faceAxisDistance(worldPos, 0);
  for (int f = 1; f < count; ++f) {
    float d = faceAxisDistance(worldPos, f);
    if (d > best) {  // NaN never wins: a NaN point stays on face 0 and fails its w test
      best = d;
      face = f;
    }
  }
  return face;
}

ShadowCoord layoutShadowCoord(vec3 worldPos) {
  // Under a directional or spot light the layout gives one focused view (count 1).
  int count = int(lightViewInfo.x + 0.5);
  return layoutShadowCoordIn(worldPos, count > 1 ? nearestFace(worldPos, count) : 0);
}
