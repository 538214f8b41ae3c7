// Convolution shadow maps (Annen et al. 2007; the notes' section 3): the Fourier series of the
// depth test (convolution_series.glsl), basis images pre-filtered like colour.
#include "representations/prefiltered/moment_math.glsl"
#include "representations/prefiltered/convolution_series.glsl"

void representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS]) {
  for (int t = 0; t < SL_MOMENT_TARGETS; ++t) m[t] = vec4(0.0);
  convolutionBasis(z, m);
}

float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth) {
  return convolutionShape(convolutionStep(m, receiverDepth));
}
#include "representations/prefiltered/moment_maps.glsl"
