// Visibility against receiver depth at one texel of a pre-filtered map: pixel x of the
// u_samples x 1 target evaluates representationFromMoments at receiver depth x / (samples - 1)
// on the filtered moments at u_uvLayer (the plot of `shadowlab plot`). Unclamped.
// Needs the technique prelude (the representation module).
uniform vec3 u_uvLayer;
uniform float u_samples;
layout(location = 0) out vec4 o_result;

void main() {
  vec4 m[SL_MOMENT_TARGETS];
  momentsAt(u_uvLayer, m);
  float d = floor(gl_FragCoord.x) / max(u_samples - 1.0, 1.0);
  o_result = vec4(representationFromMoments(m, d), 0.0, 0.0, 1.0);
}
