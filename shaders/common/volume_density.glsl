// The density of the scene's procedural media: the same function as app/scene/volume_density.cpp
// (exact 32-bit integer hash, same float steps), so the deep shadow map and the reference
// integrate the same smoke. Volumes come from the storage block SlVolumes (VolumesBuffer).
struct SlVolume {
  vec4 centerShape;         // xyz centre, w: 0 box, 1 sphere
  vec4 halfSizeExtinction;  // xyz half size (sphere: x radius), w sigma_t
  vec4 noise;               // scale, amount, octaves, seed
};
layout(std430) readonly buffer SlVolumes {
  vec4 volumeHeader;  // x: count
  SlVolume volumes[];
};

uint volumeHash(ivec3 c, uint seed) {
  uint h = uint(c.x) * 73856093u ^ uint(c.y) * 19349663u ^ uint(c.z) * 83492791u ^ seed * 2654435761u;
  h = h * 747796405u + 2891336453u;
  h = ((h >> ((h >> 28u) + 4u)) ^ h) * 277803737u;
  return (h >> 22u) ^ h;
}

float volumeLattice(ivec3 c, uint seed) { return float(volumeHash(c, seed) >> 8u) * (1.0 / 16777216.0); }

float volumeSmooth(float t) { return t * t * (3.0 - 2.0 * t); }

float volumeValueNoise(vec3 p, uint seed) {
  vec3 f = floor(p);
  vec3 t = p - f;
  ivec3 c = ivec3(f);
  float u = volumeSmooth(t.x), v = volumeSmooth(t.y), w = volumeSmooth(t.z);
  float x00 = mix(volumeLattice(c, seed), volumeLattice(c + ivec3(1, 0, 0), seed), u);
  float x10 = mix(volumeLattice(c + ivec3(0, 1, 0), seed), volumeLattice(c + ivec3(1, 1, 0), seed), u);
  float x01 = mix(volumeLattice(c + ivec3(0, 0, 1), seed), volumeLattice(c + ivec3(1, 0, 1), seed), u);
  float x11 = mix(volumeLattice(c + ivec3(0, 1, 1), seed), volumeLattice(c + ivec3(1, 1, 1), seed), u);
  return mix(mix(x00, x10, v), mix(x01, x11, v), w);
}

float volumeFbm(vec3 p, int octaves, uint seed) {
  float sum = 0.0, amplitude = 0.5, total = 0.0;
  for (int o = 0; o < octaves; ++o) {
    sum += amplitude * volumeValueNoise(p, seed + uint(o));
    total += amplitude;
    p *= 2.0;
    amplitude *= 0.5;
  }
  return total > 0.0 ? sum / total : 0.0;
}

bool volumeInside(SlVolume v, vec3 p) {
  vec3 d = p - v.centerShape.xyz;
  if (v.centerShape.w > 0.5) return dot(d, d) <= v.halfSizeExtinction.x * v.halfSizeExtinction.x;
  return all(lessThanEqual(abs(d), v.halfSizeExtinction.xyz));
}

float volumeExtinction(SlVolume v, vec3 p) {
  if (!volumeInside(v, p)) return 0.0;
  float amount = v.noise.y;
  if (amount <= 0.0) return v.halfSizeExtinction.w;
  float n = volumeFbm((p - v.centerShape.xyz) * v.noise.x, int(v.noise.z + 0.5), uint(v.noise.w + 0.5));
  n = clamp(2.5 * (n - 0.5) + 0.5, 0.0, 1.0);
  return v.halfSizeExtinction.w * ((1.0 - amount) + amount * n);
}

// Ray parameters where origin + t*dir is inside the volume; false when the ray misses it.
bool volumeRange(SlVolume v, vec3 origin, vec3 dir, out float t0, out float t1) {
  vec3 o = origin - v.centerShape.xyz;
  t0 = 0.0;
  t1 = 0.0;
  if (v.centerShape.w > 0.5) {
    float r = v.halfSizeExtinction.x;
    float a = dot(dir, dir), b = dot(o, dir), c = dot(o, o) - r * r;
    float disc = b * b - a * c;
    if (!(disc > 0.0) || !(a > 0.0)) return false;
    float s = sqrt(disc);
    t0 = (-b - s) / a;
    t1 = (-b + s) / a;
    return true;
  }
  t0 = -1e30;
  t1 = 1e30;
  for (int k = 0; k < 3; ++k) {
    if (abs(dir[k]) < 1e-12) {
      if (abs(o[k]) > v.halfSizeExtinction[k]) return false;
      continue;
    }
    float a = (-v.halfSizeExtinction[k] - o[k]) / dir[k], b = (v.halfSizeExtinction[k] - o[k]) / dir[k];
    t0 = max(t0, min(a, b));
    t1 = min(t1, max(a, b));
  }
  return t0 < t1;
}

int volumeCount() { return int(volumeHeader.x + 0.5); }

// Sum of every volume's sigma_t at p.
float volumesExtinction(vec3 p) {
  float s = 0.0;
  for (int i = 0; i < volumeCount(); ++i) s += volumeExtinction(volumes[i], p);
  return s;
}
