// Optimized PCF (Castaño 2013, as in The Witness): a tent filter of half-width h = (N + 1) / 2
// texels (N = pcf.kernel) centred on the receiver, evaluated with hardware bilinear compares.
// Along each axis the texels under the tent are taken in pairs; one bilinear tap placed between
// a pair at fraction b / (a + b) returns a·V0 + b·V1 up to the factor a + b, the tent's own
// weights a and b of those two texels. So N = 3, 5, 7 cost 2², 3², 4² taps where a texel-by-texel
// tent reads (N + 1)². SL_TENT_TEXEL_BY_TEXEL evaluates that texel-by-texel tent instead: the
// check that the taps reproduce it (techniques/optimized_pcf/optimized_pcf_gl_test.cpp).
#include "common/receiver_plane.glsl"
uniform sampler2DArrayShadow u_shadowMap;
uniform float u_pcf_kernel;

const int kMaxTexels = 8;  // per axis: N = 7 spans 8 texels when the receiver is off a texel centre

float tentWeight(float k, float s, float h) { return max(h - abs(k - s), 0.0); }

// The first and last texel (relative to the receiver's base texel) the tent weighs above zero.
ivec2 tentTexels(float s, float h) { return ivec2(int(floor(s - h)) + 1, int(ceil(s + h)) - 1); }

#ifdef SL_TENT_TEXEL_BY_TEXEL
float tentVisibility(vec2 base, vec2 s, float h, vec2 size, float layer, float receiverDepth, vec4 range) {
  ivec2 rx = tentTexels(s.x, h), ry = tentTexels(s.y, h);
  float lit = 0.0, total = 0.0;
  for (int y = ry.x; y <= ry.y; ++y)
    for (int x = rx.x; x <= rx.y; ++x) {
      float w = tentWeight(float(x), s.x, h) * tentWeight(float(y), s.y, h);
      // At a texel's centre the bilinear compare reads that texel alone.
      vec2 uv = lightViewTapIn((base + vec2(x, y) + 0.5) / size, range);
      lit += w * texture(u_shadowMap, vec4(uv, layer, receiverDepthAt(receiverDepth, uv, size)));
      total += w;
    }
  return lit / max(total, 1e-6);
}
#else
// One axis: tap positions (texels from the base texel) and weights, pairing texels k and k + 1,
// in the components of two vec4s (kMaxTexels / 2 = 4 taps at most): arrays indexed by a
// varying count cost llvmpipe a memory round trip per element.
int tentTaps(float s, float h, out vec4 position, out vec4 weight) {
  ivec2 range = tentTexels(s, h);
  int taps = min((range.y - range.x + 2) / 2, kMaxTexels / 2);
  for (int i = 0; i < kMaxTexels / 2; ++i) {  // a constant count: unrolled, the components fixed
    int k = range.x + 2 * i;
    float a = tentWeight(float(k), s, h);
    float b = k + 1 <= range.y ? tentWeight(float(k + 1), s, h) : 0.0;
    weight[i] = a + b;  // > 0 within the range: the tent is positive on every texel of it
    position[i] = float(k) + b / max(a + b, 1e-6);
  }
  return taps;
}

// One lookup's taps: where they fall around its base texel and how they weigh.
struct TentTaps {
  vec2 base;
  vec4 px, wx, py, wy;
  int nx, ny;
  vec2 size;
  float layer, receiverDepth;
  vec4 range;
};

// The lookup representationVisibility made last, kept so that lookups whole texels beside it
// (representationSameBeside) share its set-up: a software rasterizer runs any code once per
// group of pixels even where none of them needs it, and the set-up is most of one lookup.
TentTaps sl_lastTent;

// Tap (i, j) of the tent moved by whole texels (shift): its weight, and its compare times it.
vec2 tentTap(TentTaps t, vec2 shift, int i, int j) {
  // Kept inside the view's atlas square (lightViewTapIn): a tap at its edge texel's centre
  // reads that texel alone, as a layer of its own clamps.
  vec2 uv = lightViewTapIn((t.base + shift + vec2(t.px[i], t.py[j]) + 0.5) / t.size, t.range);
  // A tap compares four texels: the receiver's plane at the one it falls in, less the
  // plane's change over one texel (receiver-plane bias; other modes leave the depth as is).
  float depth = receiverDepthForFootprint(receiverDepthAt(t.receiverDepth, uv, t.size), t.size);
  float w = t.wx[i] * t.wy[j];
  return vec2(w * texture(u_shadowMap, vec4(uv, t.layer, depth)), w);
}

// The tent's visibility with its taps moved by whole texels (shift; 0: the lookup itself).
float tentSum(TentTaps t, vec2 shift) {
  vec2 sum = vec2(0.0);  // lit, total weight
  for (int j = 0; j < t.ny; ++j)
    for (int i = 0; i < t.nx; ++i) sum += tentTap(t, shift, i, j);
  return sum.x / max(sum.y, 1e-6);
}

float tentVisibility(vec2 base, vec2 s, float h, vec2 size, float layer, float receiverDepth, vec4 range) {
  TentTaps t;
  t.base = base;
  t.nx = tentTaps(s.x, h, t.px, t.wx);
  t.ny = tentTaps(s.y, h, t.py, t.wy);
  t.size = size;
  t.layer = layer;
  t.receiverDepth = receiverDepth;
  t.range = range;
  sl_lastTent = t;
  return tentSum(t, vec2(0.0));
}

// Whether the last lookup's tent gives f (within tolerance) at the four positions one texel
// diagonally around it: its taps moved by whole texels, in one loop over all of them (a
// neighbour's sub-texel offset, and so its taps and weights, are the lookup's own).
#define SL_REPRESENTATION_SAME_BESIDE
bool representationSameBeside(float f, float tolerance) {
  TentTaps t = sl_lastTent;
  // At least one tap per axis (as tentTaps gives for any finite offset): the loop below moves
  // to the next shift only after nx * ny taps, so an empty axis would never end it.
  t.nx = clamp(t.nx, 1, kMaxTexels / 2);
  t.ny = clamp(t.ny, 1, kMaxTexels / 2);
  vec4 lit = vec4(0.0), total = vec4(0.0);
  int i = 0, j = 0;  // counted, not divided out of n: llvmpipe divides integers lane by lane
  for (int k = 0; k < 4;) {
    vec2 tap = tentTap(t, vec2(k & 1, k >> 1) * 2.0 - 1.0, i, j);
    lit[k] += tap.x;
    total[k] += tap.y;
    if (++i == t.nx) {
      i = 0;
      if (++j == t.ny) {
        j = 0;
        ++k;
      }
    }
  }
  return all(lessThanEqual(abs(lit / max(total, vec4(1e-6)) - f), vec4(tolerance)));
}
#endif

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  vec2 size = vec2(textureSize(u_shadowMap, 0).xy);
  vec2 t = uvLayer.xy * size - 0.5;  // texel centres at whole numbers
  vec2 base = floor(t);
  float h = 0.5 * (u_pcf_kernel + 1.0);
  return tentVisibility(base, t - base, h, size, uvLayer.z, receiverDepth, lightViewTapRange(sl_view, size));
}

// How far from the receiver (in texels) the filter reads with most of its weight: scales the
// slope bias. The tent reaches h texels; beyond h - 1/2 its weights are below a quarter of its peak.
float representationFilterRadius(vec3 p, int view) { return 0.5 * u_pcf_kernel; }
