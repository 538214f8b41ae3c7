// Shared depth bias (survey: "bias"). SL_BIAS_MODE (from the renderer's prelude, the index of
// bias.mode): 0 none, 1 constant, 2 slope-scaled, 3 normal offset.
#ifndef SL_BIAS_MODE
#define SL_BIAS_MODE 2
#endif
uniform float u_bias_constant;
uniform float u_bias_slope;
uniform float u_bias_normal;

// Receiver position moved along its normal (normal-offset shadows).
vec3 biasReceiverPosition(vec3 p, vec3 n, float cosTheta, int view) {
#if SL_BIAS_MODE == 3
  float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  return p + n * (u_bias_normal * layoutTexelWorldSize(p, view) * sinTheta);
#else
  return p;
#endif
}

// Depth offset subtracted from the receiver before the comparison.
float biasDepth(vec3 p, float cosTheta, int view) {
#if SL_BIAS_MODE == 0
  return 0.0;
#else
  float bias = u_bias_constant;
#if SL_BIAS_MODE == 2
  {
    // A receiver tilted by theta changes depth by tan(theta) per world unit; a filter that
    // reads texels r away from the receiver sees that change over r more texels.
    float tanTheta = clamp(sqrt(max(1.0 - cosTheta * cosTheta, 0.0)) / max(cosTheta, 1e-4), 0.0, 20.0);
    float texels = u_bias_slope + representationFilterRadius();
    bias += texels * tanTheta * layoutTexelWorldSize(p, view) * layoutDepthScale(view);
  }
#endif
  return bias;
#endif
}
