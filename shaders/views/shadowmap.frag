// The shadow map as the light sees it, letterboxed into the view, near = bright. With several
// light views (cascades) their layers are tiled side by side.
uniform sampler2DArray u_shadowDepth;
uniform vec2 u_viewSize;
in vec2 v_uv;
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
  o_color = vec4(vec3(d >= 1.0 ? 0.0 : pow(1.0 - d, 1.5) * 0.9 + 0.1), 1.0);
}
