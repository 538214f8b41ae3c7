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

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  ivec2 px = ivec2(gl_FragCoord.xy);
  uint pixel = uint(px.y * u_izbWidth + px.x);
  uint bit = 1u << (pixel & 31u);
  if ((fallbackBits[pixel >> 5] & bit) != 0u) return receiverDepth <= texture(u_shadowMap, uvLayer).r ? 1.0 : 0.0;
  return (shadowBits[pixel >> 5] & bit) != 0u ? 0.0 : 1.0;
}

float representationFilterRadius(vec3 p, int view) { return 0.0; }
