// Where a G-buffer pixel's receiver reads the shadow map, for the soft techniques' screen-space
// passes (pcss's blocker search, the pre-filtered soft views): the same view choice and bias as
// the visibility test (common/visibility_term.glsl, included with SL_DEFERRED before this file).
// False where the visibility term decides without the map (background, facing away, outside
// the spot's cone or every view).
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;

bool receiverShadowCoord(ivec2 pixel, out vec3 uvLayer, out float depth) {
  uvLayer = vec3(0.0);
  depth = 0.0;
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) return false;
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  vec3 F = gbufferFacetNormal(pixel, N);
  vec3 L = directionToLight(P.xyz);
  float cosTheta = dot(N, L);
  if (!surfaceFacesLight(P.xyz, N, F, L)) return false;
  ShadowCoord pick = layoutShadowCoord(P.xyz);
  if (pick.view < 0) return false;
  int view = pick.view;
  ShadowCoord sc = layoutShadowCoordIn(biasReceiverPosition(P.xyz, N, cosTheta, view), view);
  if (shadowCoordOffMap(sc)) return false;
  depth = sc.depth - biasDepth(P.xyz, cosTheta, view);
#if defined(SL_BIAS_MODE_IS_RECEIVER_PLANE) || defined(SL_RECEIVER_PLANE_ALWAYS)
  sl_receiverPlane = vec4(sc.uv, receiverPlaneGradient(P.xyz, F, view, sc));
#ifdef SL_HAS_RECEIVER_PLANE
  setReceiverPlaneProjective(P.xyz, F, view);
#endif
#endif
  uvLayer = vec3(sc.uv, lightViewLayer(view));
  sl_view = view;
  return true;
}
