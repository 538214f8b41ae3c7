// Heat map of shadow-map sampling density: how many screen pixels one texel covers (the
// survey's dp/ds). Red: one texel spreads over many pixels (undersampling, blocky shadows);
// green: about one texel per pixel; blue: many texels per pixel (oversampling, wasted texels).
uniform sampler2D u_gPosition;
out vec4 o_color;

// t in [0, 1]: blue .. cyan .. green .. yellow .. red. The same stops as the on-screen key
// (app/render/view_keys.cpp, "aliasing"): five so that a map far too small still shows gradation.
vec3 aliasingHeat(float t) {
  const vec3 stops[5] = vec3[5](vec3(0.10, 0.30, 1.00), vec3(0.10, 0.75, 0.90), vec3(0.10, 0.80, 0.20),
                                vec3(0.95, 0.85, 0.10), vec3(1.00, 0.10, 0.05));
  float x = clamp(t, 0.0, 1.0) * 4.0;
  int i = min(int(floor(x)), 3);
  return mix(stops[i], stops[i + 1], x - float(i));
}

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) { o_color = vec4(0.1, 0.1, 0.12, 1.0); return; }
  vec4 Px = texelFetch(u_gPosition, pixel + ivec2(1, 0), 0);
  vec4 Py = texelFetch(u_gPosition, pixel + ivec2(0, 1), 0);
  if (Px.w < 0.5) Px = vec4(2.0 * P.xyz - texelFetch(u_gPosition, pixel - ivec2(1, 0), 0).xyz, 1.0);
  if (Py.w < 0.5) Py = vec4(2.0 * P.xyz - texelFetch(u_gPosition, pixel - ivec2(0, 1), 0).xyz, 1.0);
  // The neighbours in the same view as the pixel: a partition border is not a density change.
  ShadowCoord c = layoutShadowCoord(P.xyz);
  int view = max(c.view, 0);
  vec2 t = c.uv * u_shadowMapSize;
  vec2 dx = layoutShadowCoordIn(Px.xyz, view).uv * u_shadowMapSize - t;
  vec2 dy = layoutShadowCoordIn(Py.xyz, view).uv * u_shadowMapSize - t;
  float texelsPerPixel = abs(dx.x * dy.y - dx.y * dy.x);  // area of one pixel in texels
  float pixelsPerTexel = 1.0 / max(texelsPerPixel, 1e-8);
  // log2 scale over [-12, 12] (kAliasingLog2Range): 4096 pixels per texel = red, 4096 texels
  // per pixel = blue, one texel per pixel = green; wide enough that a 128-texel map still grades.
  float t01 = 0.5 + 0.5 * clamp(log2(pixelsPerTexel) / 12.0, -1.0, 1.0);
  o_color = vec4(aliasingHeat(t01), 1.0);
}
