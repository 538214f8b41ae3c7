// Debug view `izb-lists`: the light-space grid of the irregular z-buffer, each cell coloured by
// the length of its sample list (heat key, log scale: black = empty, blue 1 sample, green 8,
// yellow ~ 24, red >= 64; white = the cell's list lost samples to the capacity). The grid is
// stretched over the viewport (light-space x to the right, y up).
#include "passes/izb_common.glsl"
in vec2 v_uv;
out vec4 o_color;

vec3 heat(float t) {  // 0..1 -> blue, cyan, green, yellow, red
  return clamp(vec3(1.5 - abs(4.0 * t - 4.0), 1.5 - abs(4.0 * t - 2.5), 1.5 - abs(4.0 * t - 0.5)), 0.0, 1.0);
}

void main() {
  ivec2 cell = clamp(ivec2(v_uv * float(u_izbGrid)), ivec2(0), ivec2(u_izbGrid - 1));
  uint index = uint(cell.y * u_izbGrid + cell.x);
  uint n = offsets[index + 1u] - offsets[index];
  if (n == 0u) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);
    return;
  }
  if (offsets[index + 1u] > uint(u_izbCapacity)) {
    o_color = vec4(1.0);
    return;
  }
  o_color = vec4(heat(clamp(log2(float(n)) / 6.0, 0.0, 1.0)), 1.0);
}
