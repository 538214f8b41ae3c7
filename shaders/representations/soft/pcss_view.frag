// Debug views of the PCSS blocker search: `blocker-depth` (receiver-to-blocker distance over the
// light view's depth range, log scaled so contacts are told apart) and `penumbra`
// (filter radius in texels, log scaled from 1 to pcss.max_radius). Black: no blocker found (lit); grey: not
// searched (background, facing away, outside the map, or a point
// light: no search pass).
// u_pcssBlocker is declared by the technique's pcss module (prelude, SL_AREA_LIGHT).
out vec4 o_color;

// Blue -> cyan -> green -> yellow -> red over t in [0,1].
vec3 softRamp(float t) {
  t = clamp(t, 0.0, 1.0);
  return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

void main() {
#ifdef SL_AREA_LIGHT
  vec4 b = pcssBlockerHere();
#else
  vec4 b = vec4(0.0);  // a point light: no search ran
#endif
  if (b.w <= 0.0) {
    o_color = vec4(0.25, 0.25, 0.25, 1.0);
    return;
  }
  if (b.z < 0.5) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
#ifdef SL_VIEW_PENUMBRA
  // The radius the test uses in the first view (cascades: the nearest split's texels).
  // Log scale: 1 texel (the minimum kernel) blue, pcss.max_radius red.
  float r = clamp(b.y / lightViewRange[0].z, kPcssMinRadius, u_pcss_max_radius);
  float t = log2(r / kPcssMinRadius) / max(log2(u_pcss_max_radius / kPcssMinRadius), 1e-3);
#else
  // Log scale over the depth range: contacts blue, 1/64 of the range green, the full range red.
  float t = log(1.0 + 64.0 * b.x / max(lightViewRange[0].y - lightViewRange[0].x, 1e-6)) / log(65.0);
#endif
  o_color = vec4(softRamp(t), 1.0);
}
