// One silhouette point per texel: the edge clipped to this texel (Liang-Barsky), the clipped
// part's midpoint in texel-local coordinates [0,1]^2. Several edges in one texel: the last one
// drawn wins (a known limit of the paper's one point per texel).
flat in vec2 g_a, g_b;
flat in float g_depthA, g_depthB;
uniform float u_silSize;
uniform float u_silhouette_hidden_bias;
out vec2 o_point;

void main() {
  vec2 c = floor(gl_FragCoord.xy);
  // A view packed into a shared layer keeps to its triangle (LightView::packedTriangle).
  vec2 sides = packedTriangleSides((gl_FragCoord.xy / u_silSize) * 2.0 - 1.0, u_shadowView);
  if (min(sides.x, sides.y) < 0.0) discard;
  vec2 d = g_b - g_a;
  float t0 = 0.0, t1 = 1.0;
  for (int i = 0; i < 2; ++i) {
    if (abs(d[i]) < 1e-7) {
      if (g_a[i] < c[i] || g_a[i] > c[i] + 1.0) discard;
    } else {
      float ta = (c[i] - g_a[i]) / d[i], tb = (c[i] + 1.0 - g_a[i]) / d[i];
      t0 = max(t0, min(ta, tb));
      t1 = min(t1, max(ta, tb));
    }
  }
  if (t0 > t1) discard;
  float tm = 0.5 * (t0 + t1);
  vec2 p = g_a + d * tm;
  float depth = mix(g_depthA, g_depthB, tm);
  // Hidden edges: all four depth samples at the texel's corners are nearer than the edge point
  // (another caster in front); storing it would bend the edge of the caster that is seen.
  ivec2 ic = ivec2(c);
  int size = int(u_silSize);
  float farthest = 0.0;
  for (int k = 0; k < 4; ++k) {
    ivec2 s = clamp(ic + ivec2(k & 1, k >> 1), ivec2(0), ivec2(size - 1));
    farthest = max(farthest, texelFetch(u_shadowMap, ivec3(s, int(lightViewLayer(u_shadowView))), 0).r);
  }
  if (depth > farthest + u_silhouette_hidden_bias) discard;
  o_point = clamp(p - c, vec2(0.0), vec2(1.0));
}
