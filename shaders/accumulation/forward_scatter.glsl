// Forward shadow mapping's scatter (forward.scatter): what the texel pass
// (accumulation/forward_splat.comp) and its rasterized large splats
// (accumulation/forward_splat_quad.*) share beyond the splat itself (accumulation/forward_splat.glsl).
#include "accumulation/forward_splat.glsl"
#include "accumulation/forward_large.glsl"

const int kInlinePixels = 64;  // splats of at most this many pixels are tested in the texel pass

// Each pixel's receiver record (forwardReceiver), taken once by the receivers pass
// (accumulation/forward_receivers.comp), not by every splat whose rectangle covers the pixel.
uniform sampler2D u_forwardReceivers;

bool lightsPixel(ivec2 pixel, float sampleDepth, vec2 texel) {
  return receiverLit(texelFetch(u_forwardReceivers, pixel, 0), sampleDepth, texel);
}
