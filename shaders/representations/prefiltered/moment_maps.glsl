// Lookup side of the pre-filtered representations. A representation module defines
//   void  representationMoments(float z, out vec4 m[SL_MOMENT_TARGETS])   (shadow pass)
//   float representationFromMoments(vec4 m[SL_MOMENT_TARGETS], float receiverDepth)
// and includes this file, which samples the filtered moment targets (bilinear, or trilinear at
// the mip level as wide as filter.width) and gives representationVisibility.
// SL_MOMENT_TARGETS, SL_MOMENT_FLOAT_BITS and SL_MOMENT_MIPMAP come from MomentMapState.
uniform float u_filter_width;
uniform sampler2DArray u_moments0;
#if SL_MOMENT_TARGETS > 1
uniform sampler2DArray u_moments1;
#endif
#if SL_MOMENT_TARGETS > 2
uniform sampler2DArray u_moments2;
#endif
#if SL_MOMENT_TARGETS > 3
uniform sampler2DArray u_moments3;
#endif
#if SL_MOMENT_TARGETS > 4
uniform sampler2DArray u_moments4;
#endif
#if SL_MOMENT_TARGETS > 5
uniform sampler2DArray u_moments5;
#endif
#if SL_MOMENT_TARGETS > 6
uniform sampler2DArray u_moments6;
#endif
#if SL_MOMENT_TARGETS > 7
uniform sampler2DArray u_moments7;
#endif

void momentsAt(vec3 uvLayer, out vec4 m[SL_MOMENT_TARGETS]) {
#ifdef SL_MOMENT_MIPMAP
  // The level whose texels are filter.width texels of level 0 wide: every filter method then
  // averages over the same footprint (an explicit level: the visibility code is not in
  // uniform control flow, where screen-space derivatives would be undefined).
  float lod = log2(max(u_filter_width, 1.0));
#else
  float lod = 0.0;
#endif
  m[0] = textureLod(u_moments0, uvLayer, lod);
#if SL_MOMENT_TARGETS > 1
  m[1] = textureLod(u_moments1, uvLayer, lod);
#endif
#if SL_MOMENT_TARGETS > 2
  m[2] = textureLod(u_moments2, uvLayer, lod);
#endif
#if SL_MOMENT_TARGETS > 3
  m[3] = textureLod(u_moments3, uvLayer, lod);
#endif
#if SL_MOMENT_TARGETS > 4
  m[4] = textureLod(u_moments4, uvLayer, lod);
#endif
#if SL_MOMENT_TARGETS > 5
  m[5] = textureLod(u_moments5, uvLayer, lod);
#endif
#if SL_MOMENT_TARGETS > 6
  m[6] = textureLod(u_moments6, uvLayer, lod);
#endif
#if SL_MOMENT_TARGETS > 7
  m[7] = textureLod(u_moments7, uvLayer, lod);
#endif
}

float representationVisibility(vec3 uvLayer, float receiverDepth) {
  vec4 m[SL_MOMENT_TARGETS];
  momentsAt(uvLayer, m);
  float v = representationFromMoments(m, receiverDepth);
  // Last line of defence only: the tests require representationFromMoments itself to be finite
  // and within [0,1] for every moment set the filters can produce.
  return isnan(v) ? 1.0 : clamp(v, 0.0, 1.0);
}

// Half the filter's footprint: the slope bias then covers the depth range of a tilted receiver
// across the kernel, as for PCF (the Gaussian CDF reads a receiver at its own mean depth as
// half shadowed without it).
float representationFilterRadius() { return 0.5 * max(u_filter_width, 1.0); }
