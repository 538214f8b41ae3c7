// Test probe (techniques/deep/deep_gl_test.cpp): sigma_t of the scene's volumes at given points,
// so the GLSL density can be compared with app/scene/volume_density.cpp.
#include "common/volume_density.glsl"
layout(local_size_x = 64) in;
layout(std430) readonly buffer Points { vec4 points[]; };
layout(std430) writeonly buffer Values { float values[]; };
uniform int u_count;

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i < u_count) values[i] = volumesExtinction(points[i].xyz);
}
