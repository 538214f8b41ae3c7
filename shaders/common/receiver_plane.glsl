// Receiver-plane depth bias (Isidoro 2006, "Shadow mapping: GPU-based tips and techniques";
// Schüler 2006): a lookup at shadow-map position `tap` compares the stored depth with the
// receiver's plane extrapolated to that position instead of the receiver's own depth, so a
// tilted receiver does not shadow itself however steep it is (grazing light), without the large
// slope-scaled offsets that detach contact shadows. bias.mode = receiver-plane (SL_BIAS_MODE_IS_RECEIVER_PLANE)
// only; with any other mode the functions below return the receiver's depth unchanged.
// Set by the visibility term (common/visibility_term.glsl) before each lookup: xy the receiver's
// uv, zw d(stored depth)/d(uv) of its plane in that view.
vec4 sl_receiverPlane = vec4(0.0);
// The map's texels per side for that gradient (0: no plane set, e.g. views and probes).
float sl_receiverPlaneTexels = 0.0;
// Projective views (SL_LAYOUT_PROJECTIVE: uv = clip.xy / clip.w of the view's matrix): over a
// plane z/w and 1/w are affine in uv (z: the stored light-view depth, w: the clip w; a point
// light's face or a spot has w = z), while z itself is not, so across a wide perspective face the
// linear extrapolation above bends off the plane (a 141° tetrahedron face striped PCSS with
// self-shadowing). Set by setReceiverPlaneProjective (common/bias.glsl): xy d(z/w)/d(uv), zw
// d(1/w)/d(uv); the base holds z/w and 1/w at the receiver and the view's near and far (far >
// near: in use).
vec4 sl_receiverPlaneProjective = vec4(0.0);
vec4 sl_receiverPlaneProjectiveBase = vec4(0.0);
#define SL_HAS_RECEIVER_PLANE

// The receiver's depth at a tap at `tapUV` read by a nearest-texel lookup: the plane at the
// centre of the texel the tap falls in (that is where the stored depth was rasterized).
float receiverDepthAt(float receiverDepth, vec2 tapUV, vec2 mapSize) {
#ifdef SL_BIAS_MODE_IS_RECEIVER_PLANE
  vec2 centre = (floor(tapUV * mapSize) + 0.5) / mapSize;
  vec4 base = sl_receiverPlaneProjectiveBase;
  if (base.w > base.z) {
    vec2 d = centre - sl_receiverPlane.xy;
    float a = base.x + dot(sl_receiverPlaneProjective.xy, d), b = base.y + dot(sl_receiverPlaneProjective.zw, d);
    // The tap's ray meets the plane behind the light, or at infinity: no receiver in front of
    // anything drawn there (the far plane's value, as the linear form's clamp gives).
    if (!(b > 0.0)) return 1.0;
    return min(receiverDepth + (a / b - base.x / base.y) / (base.w - base.z), 1.0);
  }
  // Beyond the far plane (1) the map holds its clear value 1: the plane extrapolated past it
  // must compare as lit there, not as behind the "caster" at 1.
  return min(receiverDepth + dot(sl_receiverPlane.zw, centre - sl_receiverPlane.xy), 1.0);
#else
  return receiverDepth;
#endif
}

// For filters the hardware does (bilinear compare): the plane's largest change over the four
// texels read, subtracted once (receiver-plane bias cannot be applied per tap there).
float receiverDepthForFootprint(float receiverDepth, vec2 mapSize) {
#ifdef SL_BIAS_MODE_IS_RECEIVER_PLANE
  return receiverDepth - dot(abs(sl_receiverPlane.zw), 1.0 / mapSize);
#else
  return receiverDepth;
#endif
}
