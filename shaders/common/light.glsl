// The light, specialised at compile time (SL_SPOT_LIGHT from the renderer's prelude): a
// software rasterizer runs both sides of every branch, so per-scene constants are defines.
uniform vec3 u_lightDirection;  // direction light travels, normalized
uniform vec3 u_lightPosition;
uniform float u_spotCosHalfAngle;  // -2 for a point light: no cone
uniform float u_lightRange;        // point light: distance it reaches (1e30: no limit)
uniform vec3 u_lightColor;         // intensity per channel (white: 1)

vec3 directionToLight(vec3 p) {
#ifdef SL_SPOT_LIGHT
  return normalize(u_lightPosition - p);
#else
  return -u_lightDirection;
#endif
}

// 0 outside a spot light's cone and beyond a point light's range (the reference treats those
// points as unlit too).
float spotFactor(vec3 p) {
#ifdef SL_POINT_LIGHT
  return length(p - u_lightPosition) <= u_lightRange ? 1.0 : 0.0;
#elif defined(SL_SPOT_LIGHT)
  return dot(normalize(p - u_lightPosition), u_lightDirection) >= u_spotCosHalfAngle ? 1.0 : 0.0;
#else
  return 1.0;
#endif
}

// True where the light can reach the surface at all: the shading normal N and the triangle's own
// normal F face L (the shadow terminator, where a surface shadows itself, is unlit) and p is inside
// a spot's cone and a point light's range. Every visibility test calls the rest unlit, whatever
// a map says, as the reference does.
bool surfaceFacesLight(vec3 p, vec3 N, vec3 F, vec3 L) {
  return dot(N, L) > 0.0 && dot(F, L) > 0.0 && spotFactor(p) != 0.0;
}
