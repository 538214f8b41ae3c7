// The moment map as the light sees it, a tile per layer (as views/shadowmap.frag): one stored
// channel (view.channel), or with SL_VIEW_VARIANCE the variance on a log scale from 1e-8 (dark
// blue) to 1e-1 (yellow) with its key along the bottom (a notch per decade), or with
// SL_VIEW_SIGNED a signed colour map (blue < 0 < red) for the Fourier basis images.
// Needs the technique prelude (the representation module and its moment samplers).
uniform vec2 u_viewSize;
uniform float u_view_channel;
in vec2 v_uv;
out vec4 o_color;

// A short perceptual ramp (dark blue, teal, green, yellow) for t in [0,1].
vec3 ramp(float t) {
  t = clamp(t, 0.0, 1.0);
  vec3 a = vec3(0.15, 0.1, 0.4), b = vec3(0.1, 0.5, 0.55), c = vec3(0.35, 0.75, 0.35), d = vec3(0.98, 0.9, 0.2);
  return t < 0.333 ? mix(a, b, t * 3.0) : t < 0.667 ? mix(b, c, t * 3.0 - 1.0) : mix(c, d, t * 3.0 - 2.0);
}

vec3 signedColor(float v) {
  float m = clamp(abs(v), 0.0, 1.0);
  return v < 0.0 ? mix(vec3(0.95), vec3(0.15, 0.3, 0.9), m) : mix(vec3(0.95), vec3(0.9, 0.2, 0.1), m);
}

const float kLogLow = -8.0, kLogHigh = -1.0;

vec3 texelColor(vec4 m[SL_MOMENT_TARGETS]) {
#ifdef SL_VIEW_VARIANCE
  float variance = representationVariance(m);
  return variance <= 0.0 ? vec3(0.0) : ramp((log(variance) / log(10.0) - kLogLow) / (kLogHigh - kLogLow));
#else
  int channel = clamp(int(u_view_channel + 0.5), 0, 4 * SL_MOMENT_TARGETS - 1);
  float v = m[channel / 4][channel % 4];
  if (isnan(v) || isinf(v)) return vec3(1.0, 0.0, 1.0);
#ifdef SL_VIEW_SIGNED
  return signedColor(v);
#else
  // Values beyond [0,1] (exponential warps) fade from white toward yellow per decade.
  return v <= 1.0 ? vec3(max(v, 0.0)) : mix(vec3(1.0), vec3(1.0, 0.8, 0.1), clamp(log(v) / log(1e6), 0.0, 1.0));
#endif
#endif
}

void main() {
  int layers = textureSize(u_moments0, 0).z;
  int columns = int(ceil(sqrt(float(layers))));
  int rows = (layers + columns - 1) / columns;
#ifdef SL_VIEW_VARIANCE
  // The colour key: the bottom band of the view, one notch per decade.
  float keyHeight = max(6.0, 0.06 * u_viewSize.y);
  if (gl_FragCoord.y < keyHeight) {
    float t = gl_FragCoord.x / u_viewSize.x;
    float decade = t * (kLogHigh - kLogLow);
    bool notch = abs(decade - floor(decade + 0.5)) * u_viewSize.x / (kLogHigh - kLogLow) < 1.0;
    o_color = vec4(notch ? vec3(1.0) : ramp(t), 1.0);
    return;
  }
  vec2 area = u_viewSize - vec2(0.0, keyHeight);
  vec2 frag = gl_FragCoord.xy - vec2(0.0, keyHeight);
#else
  vec2 area = u_viewSize;
  vec2 frag = gl_FragCoord.xy;
#endif
  float side = min(area.x / float(columns), area.y / float(rows));
  vec2 grid = (frag - 0.5 * (area - side * vec2(columns, rows))) / side;
  ivec2 cell = ivec2(floor(grid));
  int layer = (rows - 1 - cell.y) * columns + cell.x;
  if (any(lessThan(grid, vec2(0.0))) || cell.x >= columns || cell.y >= rows || layer >= layers) {
    o_color = vec4(0.08, 0.08, 0.1, 1.0);
    return;
  }
  vec4 m[SL_MOMENT_TARGETS];
  momentsAt(vec3(fract(grid), float(layer)), m);
  o_color = vec4(texelColor(m), 1.0);
}
