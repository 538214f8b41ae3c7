// Irregular z-buffer (techniques/irregular/): visibility was decided per eye sample by the
// passes before shading (one shadow bit per pixel); this module only reads the bit of the pixel
// being shaded. Samples the lists could not hold (capacity overflow, behind a spot light's
// plane) fall back to the nearest-depth test of the shadow map, with its usual bias.
// Needs gl_FragCoord at the G-buffer's pixel: every caller (forward, visibility, pixel-correct
// scene pass, debug views) is a full-viewport pass of the same size.
// Visibility exists only at the G-buffer's samples (shaders/passes/volumes.frag asks).
#define SL_PER_PIXEL_VISIBILITY
uniform sampler2DArray u_shadowMap;
uniform int u_izbWidth;
layout(std430) readonly buffer IzbBits { uint shadowBits[]; };
layout(std430) readonly buffer IzbFallback { uint fallbackBits[]; };

// The last lookup: whether it fell back to the map, and where (representationSameBeside).
bool sl_izbFellBack = false;
vec3 sl_izbLastUvLayer = vec3(0.0);
float sl_izbLastDepth = 0.0;

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  ivec2 px = ivec2(gl_FragCoord.xy);
  uint pixel = uint(px.y * u_izbWidth + px.x);
  uint bit = 1u << (pixel & 31u);
  sl_izbFellBack = (fallbackBits[pixel >> 5] & bit) != 0u;
  sl_izbLastUvLayer = uvLayer;
  sl_izbLastDepth = receiverDepth;
  if (sl_izbFellBack) return receiverDepth <= texture(u_shadowMap, uvLayer).r ? 1.0 : 0.0;
  return (shadowBits[pixel >> 5] & bit) != 0u ? 0.0 : 1.0;
}

// Whether the last lookup gives f at the four map positions one texel diagonally around it
// (common/visibility_term.glsl, visibilityUnambiguous): a listed sample's bit is exact, no shift
// of the map moves it; a sample that fell back tests the map there. The generic form asked the
// whole lookup four times (the bits read again), which llvmpipe runs for every pixel.
#define SL_REPRESENTATION_SAME_BESIDE
bool representationSameBeside(float f, float tolerance) {
  float texel = 1.0 / u_shadowMapSize;  // as the generic form (every layout declares it)
  bool same = true;
  for (int k = 0; k < 4; ++k) {
    vec2 uv = clamp(sl_izbLastUvLayer.xy + (vec2(k & 1, k >> 1) * 2.0 - 1.0) * texel, vec2(0.0), vec2(1.0));
    float v = sl_izbLastDepth <= texture(u_shadowMap, vec3(uv, sl_izbLastUvLayer.z)).r ? 1.0 : 0.0;
    same = same && abs(v - f) <= tolerance;
  }
  return !sl_izbFellBack || same;
}

// The confidence of Scherzer et al. (eq. 5) measures how far a map lookup sat from its texel's
// centre. A listed sample's bit is the exact answer at the pixel (the reference's ray), so its
// confidence is 1: an accumulation's confidence view shows where the map decided instead (the
// fallen-back samples, with the map's own confidence). Beyond the papers.
#define SL_REPRESENTATION_CONFIDENCE
float representationConfidence(float mapConfidence) { return sl_izbFellBack ? mapConfidence : 1.0; }

float representationFilterRadius(vec3 p, int view) { return 0.0; }
