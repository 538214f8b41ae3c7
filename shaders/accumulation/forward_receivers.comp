// Forward shadow mapping's scatter, first pass: every eye pixel's receiver record
// (accumulation/forward_splat.glsl, forwardReceiver) once, for the splats to read (a pixel is
// tested by every splat whose rectangle reaches it); pixels outside the light view's map lit.
#include "accumulation/forward_scatter.glsl"
layout(rgba32f, binding = 1) uniform writeonly image2D u_receiversOut;
layout(local_size_x = 8, local_size_y = 8) in;

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(vec2(pixel), u_screenSize))) return;
  bool offMap;
  imageStore(u_receiversOut, pixel, forwardReceiver(pixel, offMap));
  if (offMap) markLit(pixel);
}
