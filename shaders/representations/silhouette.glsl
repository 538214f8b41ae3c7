// Shadow silhouette maps (Sen, Cammarano and Hanrahan 2003): the depth map's samples are the
// corners of a silhouette-map texel; where their four depth tests agree the receiver takes that
// result. Where they disagree a shadow edge crosses the texel: the lines from this texel's
// silhouette point to its four neighbours' points split it into four quadrants, one per corner,
// and the receiver takes the test of the corner whose quadrant it lies in (the survey's
// quadrant slide). A texel without a point uses its centre, so with no points at all this is the
// nearest-texel test.
#include "common/receiver_plane.glsl"
uniform sampler2DArray u_shadowMap;
uniform sampler2DArray u_silhouetteMap;
uniform float u_silhouette_reconstruct;

float silhouetteDepthTest(ivec2 t, int layer, float receiverDepth, vec2 size) {
  t = clamp(t, ivec2(0), ivec2(size) - 1);
  float depth = receiverDepthAt(receiverDepth, (vec2(t) + 0.5) / size, size);
  return depth <= texelFetch(u_shadowMap, ivec3(t, layer), 0).r ? 1.0 : 0.0;
}

// The point of texel c in c's local coordinates (its centre where no edge passes).
vec2 silhouettePoint(ivec2 c, int layer, vec2 size) {
  if (any(lessThan(c, ivec2(0))) || any(greaterThanEqual(c, ivec2(size)))) return vec2(0.5);
  vec2 p = texelFetch(u_silhouetteMap, ivec3(c, layer), 0).rg;
  return p.x < 0.0 ? vec2(0.5) : p;
}

float silhouetteAngle(vec2 v, float from) { return mod(atan(v.y, v.x) - from, 6.28318531); }

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  vec2 size = vec2(textureSize(u_shadowMap, 0).xy);
  int layer = int(uvLayer.z + 0.5);
  vec2 s = uvLayer.xy * size - 0.5;  // silhouette-texel space: depth samples at integer corners
  ivec2 c = ivec2(floor(s));
  vec2 f = s - vec2(c);
  float t00 = silhouetteDepthTest(c, layer, receiverDepth, size);
  float t10 = silhouetteDepthTest(c + ivec2(1, 0), layer, receiverDepth, size);
  float t01 = silhouetteDepthTest(c + ivec2(0, 1), layer, receiverDepth, size);
  float t11 = silhouetteDepthTest(c + ivec2(1, 1), layer, receiverDepth, size);
  if (t00 == t10 && t00 == t01 && t00 == t11) return t00;
  if (u_silhouette_reconstruct < 0.5) return f.y < 0.5 ? (f.x < 0.5 ? t00 : t10) : (f.x < 0.5 ? t01 : t11);
  vec2 p = silhouettePoint(c, layer, size);
  // Rays from p to the neighbours' points, in c's coordinates; counter-clockwise from the right
  // one: right, up, left, down. The wedge between two consecutive rays holds one corner.
  vec2 right = silhouettePoint(c + ivec2(1, 0), layer, size) + vec2(1.0, 0.0) - p;
  vec2 up = silhouettePoint(c + ivec2(0, 1), layer, size) + vec2(0.0, 1.0) - p;
  vec2 left = silhouettePoint(c - ivec2(1, 0), layer, size) - vec2(1.0, 0.0) - p;
  vec2 down = silhouettePoint(c - ivec2(0, 1), layer, size) - vec2(0.0, 1.0) - p;
  float from = atan(right.y, right.x);
  float a = silhouetteAngle(f - p, from);
  if (a < silhouetteAngle(up, from)) return t11;
  if (a < silhouetteAngle(left, from)) return t01;
  if (a < silhouetteAngle(down, from)) return t00;
  return t10;
}

// How far from the receiver (in texels) the filter reads: scales the slope bias. As the nearest
// test: the corner a receiver takes is its nearest one except beside an edge.
float representationFilterRadius(vec3 p, int view) { return 0.0; }
