// The shadowmap view's fullscreen triangle. It also estimates each layer's depth range, once:
// the fragment stage did it per pixel (144 fetches each), which made the view cost several
// times the scene's shading at 1920x1080 (#23).
uniform sampler2DArray u_shadowDepth;
out vec2 v_uv;
flat out vec2 v_layerRange[8];  // per layer (light views: at most 8), smallest and largest drawn depth

const int kGrid = 12;

// Smallest and largest depth below 1 (1 = cleared, nothing drawn) among grid samples of a layer.
vec2 layerDepthRange(int layer) {
  ivec2 size = textureSize(u_shadowDepth, 0).xy;
  vec2 range = vec2(1.0, 0.0);
  for (int y = 0; y < kGrid; ++y)
    for (int x = 0; x < kGrid; ++x) {
      ivec2 texel = ivec2((vec2(x, y) + 0.5) / float(kGrid) * vec2(size));
      float d = texelFetch(u_shadowDepth, ivec3(texel, layer), 0).r;
      if (d < 1.0) range = vec2(min(range.x, d), max(range.y, d));
    }
  return range;
}

void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  v_uv = p;
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
  int layers = min(textureSize(u_shadowDepth, 0).z, 8);
  for (int l = 0; l < 8; ++l) v_layerRange[l] = l < layers ? layerDepthRange(l) : vec2(1.0, 0.0);
}
