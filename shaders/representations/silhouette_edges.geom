// Widens each silhouette edge to a quad reaching one texel beyond it on every side, so that every
// silhouette-map texel the edge touches gets a fragment (conservative rasterization, as the paper
// does with wide lines). Positions are in silhouette-texel space: the depth map's window
// coordinates minus half a texel, so depth samples sit at integer corners.
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
in vec4 v_clip[];
in float v_depth[];
uniform float u_silSize;  // texels per side
flat out vec2 g_a, g_b;   // the edge's ends in silhouette-texel space
flat out float g_depthA, g_depthB;

void main() {
  vec4 c0 = v_clip[0], c1 = v_clip[1];
  // An end at or behind a perspective map's centre plane has no position in the map: the edge
  // is dropped (those texels keep the nearest depth test). NaN fails the test too.
  if (!(c0.w > 1e-6) || !(c1.w > 1e-6)) return;
  vec2 a = (c0.xy / c0.w * 0.5 + 0.5) * u_silSize - 0.5;
  vec2 b = (c1.xy / c1.w * 0.5 + 0.5) * u_silSize - 0.5;
  // Edges far outside the map would make huge quads; clamp them to a margin (the clipped part is
  // still exact inside the map, since the fragment shader clips the original segment).
  if (any(isnan(a)) || any(isnan(b)) || any(isinf(a)) || any(isinf(b))) return;
  vec2 d = b - a;
  float len = length(d);
  vec2 t = len > 1e-6 ? d / len : vec2(1.0, 0.0);
  vec2 n = vec2(-t.y, t.x);
  vec2 q[4] = vec2[](a - t - n, a - t + n, b + t - n, b + t + n);
  for (int i = 0; i < 4; ++i) {
    g_a = a;
    g_b = b;
    g_depthA = v_depth[0];
    g_depthB = v_depth[1];
    gl_Position = vec4(q[i] / u_silSize * 2.0 - 1.0, 0.0, 1.0);
    EmitVertex();
  }
  EndPrimitive();
}
