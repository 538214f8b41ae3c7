// A warped map's caster fragment (LogPSM: passes/shadow_warp.tesc/.tese), solved exactly. The
// tessellated chords only approximate the bent image of a caster triangle, and values
// interpolated over them are off wherever the chords are. Instead the fragment's map position
// (interpolated linearly, which is exact) is taken back through the warp to the view's clip X
// and Y, and over the triangle's plane the barycentric weights are affine in those: they give
// the caster's true depth and texture coordinate there, and whether the fragment lies on the
// triangle at all. So no chord and no coarse interior mesh draws depth or coverage that is not
// the caster's: the control stage needs fine pieces on the edges only (the mesh's union covers
// the polygon of its edge chords whatever its interior does, and what it draws beyond is
// rejected here).
// Beyond the paper: Lloyd et al. (2008) propose rasterizing the warped edges in hardware.
flat in float v_exactCaster;  // 1: the patch's interior is coarse (shadow_warp.tesc)
flat in vec3 v_weightRow0;    // barycentric weight i = dot(v_weightRow_i, (X, Y, 1))
flat in vec3 v_weightRow1;
flat in vec3 v_weightRow2;
flat in vec3 v_cornerDepth;
flat in vec3 v_leastWeights;  // a fragment is the caster's while every weight is at least this
flat in vec4 v_warpTerms;     // W = x Y + y; the log's C and δ
flat in vec2 v_cornerUv0;
flat in vec2 v_cornerUv1;
flat in vec2 v_cornerUv2;
noperspective in vec2 v_mapNdc;  // the fragment's position in the view's normalized coordinates

CasterFragment warpCasterFragment(vec3 interpolatedWorld, vec2 interpolatedUv) {
  if (v_exactCaster < 0.5)
    return CasterFragment(layoutDepth(interpolatedWorld), interpolatedUv, !layoutBehindPole(interpolatedWorld));
  // The clip coordinates the fragment's map position comes from: t through the log's inverse,
  // Y = 2t - 1 undivided, X = x' W. Over the triangle's plane the weights are affine in X and Y
  // (a patch seen edge on keeps the interpolated path: shadow_warp.tesc).
  float t = logWarpExpm1((v_mapNdc.y * 0.5 + 0.5) * v_warpTerms.z, v_warpTerms.w);  // logWarpInverse, C given
  float y = 2.0 * t - 1.0, w = v_warpTerms.x * y + v_warpTerms.y;
  vec3 clip = vec3(v_mapNdc.x * w, y, 1.0);
  vec3 weights = vec3(dot(v_weightRow0, clip), dot(v_weightRow1, clip), dot(v_weightRow2, clip));
  // Beside a bent edge the chords of the neighbouring triangle cover what this one's leave out,
  // up to the chords' error: those fragments stay (the plane continues across a smooth surface).
  // What a coarse interior folds farther out does not. NaN fails every comparison: not covered.
  bool inside = all(greaterThanEqual(weights, v_leastWeights)) && w >= 1e-3;
  vec2 uv = weights.x * v_cornerUv0 + weights.y * v_cornerUv1 + weights.z * v_cornerUv2;
  return CasterFragment(dot(weights, v_cornerDepth), uv, inside);
}
