// Shared depth bias (survey: "bias"). bias.mode reaches GLSL as the define of its chosen value
// (the renderer's prelude, core/params.h enumDefines): SL_BIAS_MODE_IS_NONE, _CONSTANT, _SLOPE
// (slope-scaled + constant), _NORMAL_OFFSET, _RECEIVER_PLANE (common/receiver_plane.glsl: the
// plane's gradient comes from receiverPlaneGradient below). Without the prelude: slope.
#if !defined(SL_BIAS_MODE_IS_NONE) && !defined(SL_BIAS_MODE_IS_CONSTANT) && !defined(SL_BIAS_MODE_IS_SLOPE) && \
    !defined(SL_BIAS_MODE_IS_NORMAL_OFFSET) && !defined(SL_BIAS_MODE_IS_RECEIVER_PLANE)
#define SL_BIAS_MODE_IS_SLOPE
#endif
uniform float u_bias_constant;
uniform float u_bias_slope;
uniform float u_bias_normal;

// Receiver position moved along its normal (normal-offset shadows).
vec3 biasReceiverPosition(vec3 p, vec3 n, float cosTheta, int view) {
#ifdef SL_BIAS_MODE_IS_NORMAL_OFFSET
  float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  return p + n * (u_bias_normal * layoutTexelWorldSize(p, view) * sinTheta);
#else
  return p;
#endif
}

// Depth offset subtracted from the receiver before the comparison.
float biasDepth(vec3 p, float cosTheta, int view) {
#ifdef SL_BIAS_MODE_IS_NONE
  return 0.0;
#else
  float bias = u_bias_constant;
#ifdef SL_BIAS_MODE_IS_SLOPE
  {
    // A receiver tilted by theta changes depth by tan(theta) per world unit; a filter that
    // reads texels r away from the receiver sees that change over r more texels.
    // No clamp below the 1e-4 floor of cos: a clamp (it was tan <= 20, 87 degrees) leaves the
    // receivers behind each texel centre of a grazing plane shadowing themselves, which shows
    // as a wedge over whole regions (a sun 0.06 degrees up has tan = 955).
    float tanTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0)) / max(cosTheta, 1e-4);
    float texels = u_bias_slope + representationFilterRadius(p, view);
    bias += texels * tanTheta * layoutTexelWorldSize(p, view) * layoutDepthScale(view);
  }
#endif
  return bias;
#endif
}

// Two steps 4 texels long on the receiver's tangent plane (normal n) at p: what the plane's
// gradients in a perspective or warped view are taken over.
void tangentSteps(vec3 p, vec3 n, int view, out vec3 s1, out vec3 s2) {
  vec3 t1 = normalize(cross(n, abs(n.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
  vec3 t2 = cross(n, t1);
  float h = 4.0 * layoutTexelWorldSize(p, view);
  s1 = t1 * h;
  s2 = t2 * h;
}

// d(f)/d(uv) of a quantity f that changes by df1 and df2 over the map steps a and b.
vec2 gradientOverSteps(vec2 a, vec2 b, float df1, float df2) {
  float det = a.x * b.y - a.y * b.x;
  return vec2(df1 * b.y - df2 * a.y, a.x * df2 - b.x * df1) / det;
}

// d(stored depth)/d(uv) of the receiver's tangent plane (normal n) at p in `view`, for
// receiver-plane depth bias. Orthographic views: exact, from the normal in light-view space
// (the window is texelWorldSize x size wide on both axes). Perspective or warped views: from two
// steps on the tangent plane projected by the layout. Bounded to one depth range per texel (an
// edge-on receiver, whose plane is a line in the map) and 0 where it is not finite.
vec2 receiverPlaneGradient(vec3 p, vec3 n, int view, ShadowCoord c0) {
  vec2 g;
#ifdef SL_PERSPECTIVE_MAP
  vec3 s1, s2;
  tangentSteps(p, n, view, s1, s2);
  ShadowCoord c1 = layoutShadowCoordIn(p + s1, view), c2 = layoutShadowCoordIn(p + s2, view);
  g = gradientOverSteps(c1.uv - c0.uv, c2.uv - c0.uv, c1.depth - c0.depth, c2.depth - c0.depth);
#else
  vec3 nl = mat3(lightViewMatrix[view]) * n;
  float nz = nl.z < 0.0 ? min(nl.z, -1e-4) : max(nl.z, 1e-4);
  g = nl.xy / nz * (lightViewRange[view].z * u_shadowMapSize) * layoutDepthScale(view);
#endif
  float perTexel = length(g) / u_shadowMapSize;
  if (isnan(perTexel) || isinf(perTexel)) return vec2(0.0);
  return perTexel > 1.0 ? g / perTexel : g;
}

#ifdef SL_HAS_RECEIVER_PLANE
// sl_receiverPlaneProjective(Base) of the receiver's tangent plane (normal n) at p in a projective
// view (common/receiver_plane.glsl), from two steps on the plane as receiverPlaneGradient takes;
// unset (the linear extrapolation) in other views and where the steps are not finite.
void setReceiverPlaneProjective(vec3 p, vec3 n, int view) {
  sl_receiverPlaneProjectiveBase = vec4(0.0);
#if defined(SL_PERSPECTIVE_MAP) && defined(SL_LAYOUT_PROJECTIVE)
  vec3 s1, s2;
  tangentSteps(p, n, view, s1, s2);
  mat4 vp = lightViewProjMatrix[view], v = lightViewMatrix[view];
  vec4 c0 = vp * vec4(p, 1.0), c1 = vp * vec4(p + s1, 1.0), c2 = vp * vec4(p + s2, 1.0);
  if (!(min(c0.w, min(c1.w, c2.w)) > 1e-6)) return;
  vec3 z = -vec3((v * vec4(p, 1.0)).z, (v * vec4(p + s1, 1.0)).z, (v * vec4(p + s2, 1.0)).z);
  vec3 invW = 1.0 / vec3(c0.w, c1.w, c2.w);
  vec3 zw = z * invW;
  vec2 u0 = c0.xy * invW.x * 0.5, a = c1.xy * invW.y * 0.5 - u0, b = c2.xy * invW.z * 0.5 - u0;
  vec4 g = vec4(gradientOverSteps(a, b, zw.y - zw.x, zw.z - zw.x), gradientOverSteps(a, b, invW.y - invW.x, invW.z - invW.x));
  if (any(isnan(g)) || any(isinf(g)) || isnan(zw.x) || isinf(zw.x)) return;
  sl_receiverPlaneProjective = g;
  sl_receiverPlaneProjectiveBase = vec4(zw.x, invW.x, lightViewRange[view].xy);
#endif
}
#endif
