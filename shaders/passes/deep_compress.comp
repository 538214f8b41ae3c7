// Deep shadow map, step 2 (Lokovic & Veach 2000, section 4): per light texel, the fragments of
// its list sorted by depth and the volumes ray-marched along the texel's light ray make one
// transmittance function T(z): the average over the texel's light-image samples of each sample's
// product of (1 - alpha) over its fragments (section 4.1, a box filter), times exp(-sigma dz) per
// march step (the march is shared by the samples, one ray per texel),
// compressed to at most SL_DEEP_NODES piecewise-linear nodes by their greedy error-bounded
// placement: each segment is extended while a line from its start stays within the tolerance
// of every vertex it spans. A texel that needs more nodes doubles its tolerance and tries again
// (counted in deepOverflow[1]). Needs the technique prelude (the light views).
#include "common/volume_density.glsl"
#include "common/light_ray.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430) readonly buffer DeepCounts { uint deepCount[]; };
layout(std430) readonly buffer DeepFragments { vec2 deepFragment[]; };
layout(std430) buffer DeepOverflow { uint deepOverflow[3]; };  // dropped, relaxed, samples
layout(rg32f, binding = 0) writeonly uniform image2DArray u_deepNodesOut;
layout(r32f, binding = 1) writeonly uniform image2DArray u_deepCountsOut;
uniform float u_deep_size;
uniform float u_deep_tolerance;
uniform vec4 u_deepWindow[SL_MAX_LIGHT_VIEWS];  // the part of each view's map uv the deep map covers

const int kRaw = 2 * SL_DEEP_FRAGMENTS + SL_DEEP_STEPS + 2;
// Width of a fragment's step in depth units: the step is a steep segment, not a jump, so every
// segment has a finite slope.
const float kStep = 1e-6;

vec2 raw[kRaw];
int rawCount = 0;
vec2 nodes[SL_DEEP_NODES];

void pushRaw(float z, float t) {
  if (rawCount > 0) z = max(z, raw[rawCount - 1].x + kStep);  // strictly increasing depth
  if (rawCount < kRaw) raw[rawCount++] = vec2(z, clamp(t, 0.0, 1.0));
}

// Sorted fragments merged with the volume march into raw vertices (depth, transmittance).
void buildFunction(uint texel, vec2 uv, int view) {
  int n = int(min(deepCount[texel], uint(SL_DEEP_FRAGMENTS)));
  float fz[SL_DEEP_FRAGMENTS], fa[SL_DEEP_FRAGMENTS];
  for (int i = 0; i < n; ++i) {
    vec2 f = deepFragment[texel * uint(SL_DEEP_FRAGMENTS) + uint(i)];
    int j = i;
    for (; j > 0 && fz[j - 1] > f.x; --j) {
      fz[j] = fz[j - 1];
      fa[j] = fa[j - 1];
    }
    fz[j] = f.x;
    fa[j] = f.y;
  }
  vec3 origin = lightRayPoint(uv, 0.0, view), dir = lightRayPoint(uv, 1.0, view) - origin;
  float d0 = 2.0, d1 = -1.0;
  for (int v = 0; v < volumeCount(); ++v) {
    float t0, t1;
    if (volumeRange(volumes[v], origin, dir, t0, t1)) {
      d0 = min(d0, max(t0, 0.0));
      d1 = max(d1, min(t1, 1.0));
    }
  }
  int steps = d1 > d0 ? SL_DEEP_STEPS : 0;
  float dz = steps > 0 ? (d1 - d0) / float(steps) : 0.0;
  float worldStep = dz * length(dir);
  // T = volume * mean over samples of sampleTransmittance[s] (each sample's product of
  // 1 - alpha so far): a fragment of sample s takes volume * sampleTransmittance[s] * alpha /
  // samples from T.
  float sampleTransmittance[16];
  for (int s = 0; s < 16; ++s) sampleTransmittance[s] = 1.0;
  float samples = float(clamp(int(deepOverflow[2]), 1, 16));  // as rasterized (deep_fragments.frag)
  float volume = 1.0, T = 1.0;
  int i = 0, k = 0;
  if (n > 0 || steps > 0) pushRaw(min(n > 0 ? fz[0] : 2.0, steps > 0 ? d0 : 2.0), 1.0);
  while (i < n || k < steps) {
    float zf = i < n ? fz[i] : 3.0, zv = k < steps ? d0 + float(k + 1) * dz : 3.0;
    if (zf <= zv) {
      pushRaw(zf, T);
      int s = clamp(int(ceil(fa[i])) - 1, 0, 15);
      float alpha = fa[i] - float(s);
      T -= volume * sampleTransmittance[s] * alpha / samples;
      sampleTransmittance[s] *= 1.0 - alpha;
      pushRaw(zf + kStep, T);
      ++i;
    } else {
      float e = exp(-volumesExtinction(origin + dir * (d0 + (float(k) + 0.5) * dz)) * worldStep);
      volume *= e;
      T *= e;
      pushRaw(zv, T);
      ++k;
    }
  }
}

// Greedy error-bounded placement; false when it needs more than SL_DEEP_NODES nodes.
bool compress(float tolerance, out int count) {
  count = 0;
  if (rawCount == 0) return true;
  nodes[0] = raw[0];
  count = 1;
  vec2 origin = raw[0];
  float lo = -1e30, hi = 1e30;
  int last = 0;
  int j = 1;
  while (j < rawCount) {
    float dz = raw[j].x - origin.x;
    float l = max(lo, (raw[j].y - tolerance - origin.y) / dz), h = min(hi, (raw[j].y + tolerance - origin.y) / dz);
    if (l <= h) {
      lo = l;
      hi = h;
      last = j++;
      continue;
    }
    if (count >= SL_DEEP_NODES) return false;
    vec2 node = vec2(raw[last].x, clamp(origin.y + 0.5 * (lo + hi) * (raw[last].x - origin.x), 0.0, 1.0));
    nodes[count++] = node;
    origin = node;
    lo = -1e30;
    hi = 1e30;
  }
  if (rawCount > 1) {
    if (count >= SL_DEEP_NODES) return false;
    float z = raw[rawCount - 1].x;
    nodes[count++] = vec2(z, clamp(origin.y + 0.5 * (lo + hi) * (z - origin.x), 0.0, 1.0));
  }
  return true;
}

void main() {
  int size = int(u_deep_size + 0.5);
  ivec3 id = ivec3(gl_GlobalInvocationID);
  if (id.x >= size || id.y >= size) return;
  uint texel = uint((id.z * size + id.y) * size + id.x);
  vec4 window = u_deepWindow[clamp(id.z, 0, SL_MAX_LIGHT_VIEWS - 1)];
  vec2 uv = window.xy + (vec2(id.xy) + 0.5) / float(size) * window.zw;
  buildFunction(texel, uv, id.z);
  float tolerance = max(u_deep_tolerance, 1e-6);
  int count = 0;
  bool relaxed = false;
  for (int attempt = 0; attempt < 40 && !compress(tolerance, count); ++attempt) {
    tolerance *= 2.0;
    relaxed = true;
  }
  if (relaxed) atomicAdd(deepOverflow[1], 1u);
  for (int k = 0; k < count; ++k) imageStore(u_deepNodesOut, ivec3(id.xy, id.z * SL_DEEP_NODES + k), vec4(nodes[k], 0, 0));
  imageStore(u_deepCountsOut, id, vec4(float(count)));
}
