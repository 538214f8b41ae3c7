// The shadow map as the light sees it, letterboxed into the view, near = bright. With several
// light views (cascades) their layers are tiled side by side. Each layer's grey ramp spans the
// depths actually in it (estimated from a 12x12 grid of texels, once, by views/shadowmap.vert),
// not the whole [0, 1] range: a warped layout (LiSPSM, PSM) packs the scene into a sliver of
// depth and would look flat grey.
uniform sampler2DArray u_shadowDepth;
uniform vec2 u_viewSize;
in vec2 v_uv;
flat in vec2 v_layerRange[8];  // views/shadowmap.vert
out vec4 o_color;

void main() {
  int layers = textureSize(u_shadowDepth, 0).z;
  int columns = int(ceil(sqrt(float(layers))));
  int rows = (layers + columns - 1) / columns;
  float side = min(u_viewSize.x / float(columns), u_viewSize.y / float(rows));
  vec2 grid = (gl_FragCoord.xy - 0.5 * (u_viewSize - side * vec2(columns, rows))) / side;
  ivec2 cell = ivec2(floor(grid));
  int layer = (rows - 1 - cell.y) * columns + cell.x;
  if (any(lessThan(grid, vec2(0.0))) || cell.x >= columns || cell.y >= rows || layer >= layers) {
    o_color = vec4(0.08, 0.08, 0.1, 1.0);
    return;
  }
  float d = texture(u_shadowDepth, vec3(fract(grid), float(layer))).r;
  if (d >= 1.0) {
    o_color = vec4(0.0, 0.0, 0.0, 1.0);  // cleared: nothing drawn there
    return;
  }
  vec2 range = v_layerRange[min(layer, 7)];
  // Padded so that depths the grid missed still grade a little beyond its ends.
  float pad = max(0.05 * (range.y - range.x), 1e-6);
  float lo = range.x <= range.y ? range.x - pad : 0.0, hi = range.x <= range.y ? range.y + pad : 1.0;
  float t = clamp((d - lo) / max(hi - lo, 1e-6), 0.0, 1.0);
  o_color = vec4(vec3(pow(1.0 - t, 1.2) * 0.9 + 0.1), 1.0);
}
