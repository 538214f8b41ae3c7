// Heat map of shadow-map sampling density: how many screen pixels one texel covers (the
// survey's dp/ds). Red: one texel spreads over many pixels (undersampling, blocky shadows);
// green: about one texel per pixel; blue: many texels per pixel (oversampling, wasted texels).
uniform sampler2D u_gPosition;
out vec4 o_color;

vec3 heat(float t) {  // t in [-1, 1]: blue .. green .. red
  return t < 0.0 ? mix(vec3(0.1, 0.8, 0.2), vec3(0.1, 0.3, 1.0), -t) : mix(vec3(0.1, 0.8, 0.2), vec3(1.0, 0.1, 0.05), t);
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
  // log4 scale: 16 pixels per texel = full red, 16 texels per pixel = full blue.
  float t01 = clamp(log2(pixelsPerTexel) / 4.0, -1.0, 1.0);
  o_color = vec4(heat(t01), 1.0);
}
