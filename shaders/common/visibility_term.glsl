// The shadow term of one covered pixel: layout projection + representation reconstruction,
// plus the shadow-test confidence of Scherzer et al. 2007 (eq. 5) for accumulations.
// Needs the technique prelude (layout + representation modules).
#include "common/light.glsl"
#include "common/bias.glsl"

// The test in one light view: x visibility (1 = lit), y confidence in [0,1] (1 = the sample
// sat on a texel centre). coord: where it read the map (uv, biased receiver depth, layer); z < -1
// when the point is outside the view's map (lit: nothing was rendered as a caster there). F: the
// triangle's own normal, whose plane is what the map rasterized (receiver-plane bias).
vec2 shadowTestIn(vec3 P, vec3 N, vec3 F, float cosTheta, int view, out vec4 coord) {
  coord = vec4(0.0, 0.0, -2.0, -1.0);
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P, N, cosTheta, view), view);
  if (shadowCoordOffMap(sc)) return vec2(1.0, 0.0);
  coord = vec4(sc.uv, sc.depth - biasDepth(P, cosTheta, view), lightViewLayer(view));
  sl_view = view;
#if defined(SL_BIAS_MODE_IS_RECEIVER_PLANE) || defined(SL_RECEIVER_PLANE_ALWAYS)
  sl_receiverPlane = vec4(sc.uv, receiverPlaneGradient(P, F, view, sc));
#ifdef SL_HAS_RECEIVER_PLANE
  setReceiverPlaneProjective(P, F, view);
#endif
  sl_receiverPlaneTexels = u_shadowMapSize;
#endif
  float visibility = representationVisibility(vec3(coord.xy, coord.w), coord.z);
  vec2 texelPos = sc.uv * u_shadowMapSize;
  vec2 fromCenter = abs(texelPos - (floor(texelPos) + 0.5));
  float confidence = 1.0 - 2.0 * max(fromCenter.x, fromCenter.y);
#ifdef SL_REPRESENTATION_CONFIDENCE
  // A representation whose answer does not come from the map's texels (an exact test) says how
  // sure its last lookup is; the texel-centre distance is what it falls back on.
  confidence = representationConfidence(confidence);
#endif
  return vec2(visibility, confidence);
}

// x: visibility (1 = lit), y: confidence. N: shading normal, F: the triangle's own normal (same
// side). coord: where the test read the map (uv, biased receiver depth, layer; of the first view
// when two are blended); z < -1 when no map lookup decided it (facing away, outside the cone,
// outside the map).
vec2 visibilityTermAt(vec3 P, vec3 N, vec3 F, out vec4 coord) {
  coord = vec4(0.0, 0.0, -2.0, -1.0);
  vec3 L = directionToLight(P);
  float cosTheta = dot(N, L);
  if (!surfaceFacesLight(P, N, F, L)) return vec2(0.0, 1.0);
  // The layout picks the view(s) at the surface point; the bias is applied within each view.
  ShadowCoord pick = layoutShadowCoord(P);
  if (pick.view < 0) return vec2(1.0, 0.0);
  // With a second view blended in, its test runs first: the first view's lookup, the one at
  // coord, is the last, so that the view, receiver plane and lookup state later lookups at coord
  // read (visibilityUnambiguous) are its own.
  vec2 second = vec2(0.0);
  float blend = pick.view2 >= 0 ? clamp(pick.weight2, 0.0, 1.0) : 0.0;
  if (blend > 0.0) {
    vec4 coord2;
    second = shadowTestIn(P, N, F, cosTheta, pick.view2, coord2);
  }
  vec2 result = shadowTestIn(P, N, F, cosTheta, pick.view, coord);
  if (blend <= 0.0) return result;
  sl_view = pick.view;  // when the first view's point was off its map, too
  return mix(result, second, blend);
}

vec2 visibilityTerm(vec3 P, vec3 N, vec3 F) {
  vec4 coord;
  return visibilityTermAt(P, N, F, coord);
}

#ifdef SL_DEFERRED
// gbufferFacetNormal
#include "common/facet.glsl"
#endif

// True when the test gives `f` at the four shadow-map positions one texel diagonally around
// `coord` (from visibilityTermAt): no rasterization (jitter) of this map could change the answer.
bool visibilityUnambiguous(vec4 coord, float f) {
  if (coord.z < -1.0) return true;
#ifdef SL_REPRESENTATION_SAME_BESIDE
  // The representation repeats its last lookup, the one at coord (visibilityTermAt makes it
  // last), moved by whole texels.
  return representationSameBeside(f, 0.01);
#else
  float texel = 1.0 / u_shadowMapSize;
  bool same = true;
  for (int k = 0; k < 4; ++k) {
    vec2 uv = clamp(coord.xy + (vec2(k & 1, k >> 1) * 2.0 - 1.0) * texel, vec2(0.0), vec2(1.0));
    same = same && abs(representationVisibility(vec3(uv, coord.w), coord.z) - f) <= 0.01;
  }
  return same;
#endif
}
