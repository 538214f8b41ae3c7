// Layered variance shadow maps (Lauritzen & McCool 2008, cited by Gumbau et al.): the depth
// range is cut into SL_LVSM_LAYERS equal layers; layer i stores the VSM moments of the depth
// warped into it, phi_i(z) = clamp((z - z_i) / (z_{i+1} - z_i), 0, 1), two channels per layer.
// A receiver in layer i is tested against layer i alone: occluders nearer than the layer map to
// 0 (they shadow fully), farther ones to 1, so depths of other layers cannot inflate the
// variance and bleed light (the overlap case), at 2 channels per layer. Just behind a layer's
// start, occluders of the layers before sit at warped 0, within the variance floor of the
// receiver: the layer before is asked too (representationFromMoments).
#include "representations/prefiltered/moment_math.glsl"
uniform float u_lvsm_min_variance;

float lvsmWarp(float z, int layer) {
  return clamp(z * float(SL_LVSM_LAYERS) - float(layer), 0.0, 1.0);
}

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) {
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) m[t] = vec4(0.0);
  for (int i = 0; i < SL_LVSM_LAYERS; ++i) {
    float w = lvsmWarp(z, i);
    if ((i & 1) == 0)
      m[i / 2].xy = vec2(w, w * w);
    else
      m[i / 2].zw = vec2(w, w * w);
  }
}

int lvsmLayerOf(float z) { return clamp(int(floor(z * float(SL_LVSM_LAYERS))), 0, SL_LVSM_LAYERS - 1); }

vec2 lvsmMoments(vec4 m[SL_MOMENT_TARGETS], int layer) { return (layer & 1) == 0 ? m[layer / 2].xy : m[layer / 2].zw; }

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  int layer = lvsmLayerOf(receiverDepth);
  // The floor in depth^2 units, scaled by the warp's derivative (layers per unit depth).
  float slope = float(SL_LVSM_LAYERS);
  float floorVariance = u_lvsm_min_variance * slope * slope;
  float p = chebyshevUpperBound(lvsmMoments(m, layer), lvsmWarp(receiverDepth, layer), floorVariance);
  // Beyond the paper: occluders of the layers before sit at warped 0 in this one, within the
  // floor of a receiver just past the layer's start, which then reads lit (a bright band along
  // each layer boundary: Sponza under a 3 degree sun, 5.9 % false light, issue #23). The layer
  // before sees them below 1, where the receiver is (behind all of that layer): the lower bound.
  if (layer > 0) p = min(p, chebyshevUpperBound(lvsmMoments(m, layer - 1), 1.0, floorVariance));
  return p;
}

// The variance view: the largest warped variance over the layers.
float representationVariance(vec4 m[SL_MOMENT_TARGETS]) {
  float v = 0.0;
  for (int i = 0; i < SL_LVSM_LAYERS; ++i) {
    vec2 mm = lvsmMoments(m, i);
    v = max(v, mm.y - mm.x * mm.x);
  }
  return v;
}
#include "representations/prefiltered/moment_maps.glsl"
