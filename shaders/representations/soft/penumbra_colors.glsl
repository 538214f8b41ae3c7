// Colours of the soft techniques' `blocker-depth` and `penumbra` views, from what a blocker
// estimate found at a pixel: b.x receiver-to-blocker distance and b.y penumbra radius (world
// units), b.z 1 = blockers found, b.w the search radius (texels; 0 = not searched).
// `blocker-depth`: the distance over the light view's depth range, log scaled so contacts are
// told apart; `penumbra` (SL_VIEW_PENUMBRA): the filter radius in texels, log scaled from 1 to
// pcss.max_radius. Black: no blocker found (lit); grey: not searched (background, facing away,
// outside the map, or a point light).

// Blue -> cyan -> green -> yellow -> red over t in [0,1].
vec3 softRamp(float t) {
  t = clamp(t, 0.0, 1.0);
  return clamp(vec3(1.5 - abs(4.0 * t - 3.0), 1.5 - abs(4.0 * t - 2.0), 1.5 - abs(4.0 * t - 1.0)), 0.0, 1.0);
}

// view, receiverDepth: where the pixel's test reads (its cascade under cascades).
vec4 penumbraViewColor(vec4 b, int view, float receiverDepth) {
  if (!(b.w > 0.0)) return vec4(0.25, 0.25, 0.25, 1.0);
  if (b.z < 0.5) return vec4(0.0, 0.0, 0.0, 1.0);
#ifdef SL_VIEW_PENUMBRA
  // The radius in texels of the view the pixel reads, as the filter uses it.
  float r = clamp(b.y / pcssTexelWorld(view, pcssLinear(receiverDepth, view)), kPcssMinRadius, u_pcss_max_radius);
  float t = log2(r / kPcssMinRadius) / max(log2(u_pcss_max_radius / kPcssMinRadius), 1e-3);
#else
  // Contacts blue, 1/64 of that view's depth range green, the full range red.
  float t = log(1.0 + 64.0 * b.x / max(lightViewRange[view].y - lightViewRange[view].x, 1e-6)) / log(65.0);
#endif
  return vec4(softRamp(t), 1.0);
}
