#include "common/shading.glsl"
in vec2 v_uv;
layout(location = 0) out vec4 o_color;
void main() { o_color = vec4(skyColor(v_uv.y), 1.0); }
