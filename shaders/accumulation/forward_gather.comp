// Forward shadow mapping (Zhang 1998) gathered: the pixels the scatter lights
// (accumulation/forward_splat.comp, forward.scatter), found per eye pixel instead of per light
// texel (beyond the paper; the image is the scatter's, holes included).
//
// A splat lights only pixels whose surface point falls in its own texel (forward.footprint
// texels wide; accumulation/forward_splat.glsl, receiverLit). So the texels that can light a
// pixel are those within forward.footprint / 2 texels of where its point falls, usually one: the
// pixel is lit when one of their splats, sized as the scatter sizes it (splatOfTexel), covers
// it and passes the depth test. One invocation per eye pixel (0.9 M at 1280x720) instead of per
// light texel (4.2 M at 2048²), and no splat loops over pixels none of which it lights.
#include "accumulation/forward_splat.glsl"
layout(local_size_x = 8, local_size_y = 8) in;

// Whether the splat of texel t covers the pixel and lights its receiver.
bool litBySplatOf(ivec2 t, ivec2 pixel, vec4 receiver) {
  float d;
  ivec2 lo, hi;
  if (!splatOfTexel(t, d, lo, hi)) return false;
  if (any(lessThan(pixel, lo)) || any(greaterThan(pixel, hi))) return false;
  return receiverLit(receiver, d, vec2(t) + 0.5);
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(vec2(pixel), u_screenSize))) return;
  bool offMap;
  vec4 receiver = forwardReceiver(pixel, offMap);
  if (offMap) markLit(pixel);
  if (receiver.w < 0.5) return;
  // The texels whose centres may lie within forward.footprint / 2 texels of the point (a
  // thousandth of a texel more against rounding; receiverLit decides exactly, as the scatter
  // does).
  vec2 reach = vec2(0.5 * u_forward_footprint + 1e-3);
  vec2 mapEnd = vec2(u_mapSize - 1);
  ivec2 first = ivec2(clamp(ceil(receiver.xy - 0.5 - reach), vec2(0.0), mapEnd));
  ivec2 last = ivec2(clamp(floor(receiver.xy - 0.5 + reach), vec2(0.0), mapEnd));
  for (int y = first.y; y <= last.y; ++y)
    for (int x = first.x; x <= last.x; ++x)
      if (litBySplatOf(ivec2(x, y), pixel, receiver)) {
        markLit(pixel);
        return;
      }
}
