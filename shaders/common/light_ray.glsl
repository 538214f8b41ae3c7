// The world point a light view's map stores: at stored depth d (light-view linear depth over
// [near, far]) on the ray through map position uv of `view`. Perspective views (spot and point
// lights) go along the texel's ray to that view distance, orthographic ones straight down the
// view axis. Needs common/light_views.glsl (the technique prelude's layout module includes it).
// The inverses are taken here, not read from the block: on llvmpipe the shader compiler folds
// them across calls, and the two inverses added to the block made the forward splat slower
// (1140 against 810 ms at 1280x720).
vec3 lightRayPoint(vec2 uv, float d, int view) {
  mat4 worldFromView = inverse(lightViewMatrix[view]);
  vec4 onPlane = inverse(lightViewProjMatrix[view]) * vec4(uv * 2.0 - 1.0, 0.0, 1.0);
  vec3 ray = (lightViewMatrix[view] * vec4(onPlane.xyz / onPlane.w, 1.0)).xyz;
  float dist = mix(lightViewRange[view].x, lightViewRange[view].y, d);
  vec3 p = lightViewRange[view].w > 0.5 ? ray * (dist / max(-ray.z, 1e-12)) : vec3(ray.xy, -dist);
  return (worldFromView * vec4(p, 1.0)).xyz;
}
