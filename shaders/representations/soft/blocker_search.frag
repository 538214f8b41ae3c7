// PCSS step 1 as a pass of its own (techniques/soft/pcss.cpp): per covered G-buffer pixel, the
// average depth of the shadow-map texels closer to the light than the receiver within the region
// the area light sees it through, as receiver-to-blocker distance and penumbra radius (world
// units).
#define SL_DEFERRED
#include "common/visibility_term.glsl"
#include "representations/soft/receiver_coord.glsl"
out vec4 o_blocker;

void main() {
  vec3 uvLayer;
  float depth;
  o_blocker = receiverShadowCoord(ivec2(gl_FragCoord.xy), uvLayer, depth) ? pcssBlockerSearch(uvLayer, depth)
                                                                          : vec4(0.0);
}
