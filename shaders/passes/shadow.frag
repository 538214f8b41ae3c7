#include "common/material.glsl"
in vec3 v_world;
in vec2 v_uv;

void main() {
  materialAlphaTest(v_uv);
  // Linear light-view depth, identical in every layout, so biases mean the same everywhere.
  gl_FragDepth = clamp(layoutDepth(v_world), 0.0, 1.0);
}
