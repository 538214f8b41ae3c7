// The PCSS penumbra model (Fernando 2005), shared by every soft representation (pcss, and the
// pre-filtered vssm and convolution-soft): the light's size, the region of the map that can hold
// a receiver's blockers, and the penumbra width by similar triangles, in world units and in
// texels of the light view a lookup reads (so the same model serves every cascade).
// lightViewRange comes from the layout (common/light_views.glsl); the parameters pcss.light_scale
// and pcss.max_radius are declared once, in techniques/soft/penumbra_params.cpp.
#include "common/light_views.glsl"
uniform float u_pcss_light_scale;
uniform float u_pcss_max_radius;
uniform float u_lightRadius;  // the scene's light.radius (spot: world disk radius; sun: tan)

const float kPcssMinRadius = 1.0;  // texels: the filter never gets sharper than ~3x3 PCF

float pcssLightSize() { return u_lightRadius * u_pcss_light_scale; }

// Light-view linear distance of a stored depth in `view`.
float pcssLinear(float stored, int view) {
  return lightViewRange[view].x + stored * (lightViewRange[view].y - lightViewRange[view].x);
}

// World size of one texel of `view` at light-view distance `dist` (perspective maps: the texel
// at unit distance times the distance; orthographic: constant).
float pcssTexelWorld(int view, float dist) {
#ifdef SL_PERSPECTIVE_MAP
  if (lightViewRange[view].w > 0.5) return lightViewRange[view].z * max(dist, 1e-6);
#endif
  return lightViewRange[view].z;
}

// Penumbra radius at a receiver at distance dR from blockers at dB (light-view distances), by
// similar triangles: sun (angular radius tan = size) size * (dR - dB); spot disk of radius size
// at the light's origin: size * (dR - dB) / dB.
float pcssPenumbraWorld(float dR, float dB) {
  float gap = max(dR - dB, 0.0);
#ifdef SL_SPOT_LIGHT
  return pcssLightSize() * gap / max(dB, 1e-4);
#else
  return pcssLightSize() * gap;
#endif
}

// Radius in texels of `view` of the region that can hold blockers of a receiver at dR: the
// cone from the receiver to the light disk, widest at the view's near plane, in texels there.
float pcssSearchTexels(int view, float dR) {
  float nearD = max(lightViewRange[view].x, 1e-4);
#ifdef SL_SPOT_LIGHT
  float world = pcssLightSize() * max(dR - nearD, 0.0) / max(dR, 1e-4);
  float texels = world / pcssTexelWorld(view, nearD);
#else
  float texels = pcssLightSize() * max(dR - nearD, 0.0) / pcssTexelWorld(view, dR);
#endif
  return clamp(texels, kPcssMinRadius, u_pcss_max_radius);
}
