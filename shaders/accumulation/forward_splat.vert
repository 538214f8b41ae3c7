// One point per light-view sample (texel of view 0): its world position rebuilt from the depth
// the shadow pass stored (light-view linear depth over [near, far]), sent forward into the eye
// view. Empty texels (nothing rasterized: depth 1) send nothing.
// The point is as large as the texel's footprint in the eye view (beyond Zhang's fixed splat):
// the distance, in pixels, from the sample to where its neighbouring texels' samples land, so a
// texel stretched over many pixels (a grazing light, a texel near the eye) still covers them;
// at least forward.splat pixels, at most kMaxSplat (forward.grow; off: forward.splat always). The fragment stage keeps the splat inside
// the texel's own light-space square, so a larger point cannot spread light across an edge.
uniform sampler2DArray u_shadowMap;  // the vertex stage gets only the layout module
uniform mat4 u_eyeViewProj;
uniform int u_mapSize;
uniform vec2 u_screenSize;
uniform float u_forward_splat;
uniform float u_forward_footprint;
uniform float u_forward_grow;  // off: Zhang's fixed forward.splat
flat out vec3 v_sample;   // the sample's world position
flat out vec2 v_texel;    // its texel, in texels

const float kMaxSplat = 255.0;  // pixels: beyond it a texel spans so much of the view that holes are the method's

// The world position of the sample of texel t with stored depth d.
vec3 sampleWorld(vec2 texel, float d) {
  mat4 view = lightViewMatrix[0];
  mat4 proj = lightViewProjMatrix[0] * inverse(view);
  vec2 ndc = texel / float(u_mapSize) * 2.0 - 1.0;
  vec4 ray = inverse(proj) * vec4(ndc, 0.0, 1.0);
  ray /= ray.w;
  float z = lightViewRange[0].x + d * (lightViewRange[0].y - lightViewRange[0].x);
  // Perspective view (spot light): along the texel's ray to that view distance; orthographic:
  // straight down the view axis.
  vec3 p = lightViewRange[0].w > 0.5 ? ray.xyz * (z / max(-ray.z, 1e-9)) : vec3(ray.xy, -z);
  return (inverse(view) * vec4(p, 1.0)).xyz;
}

// Pixels from the sample's eye position to where a neighbour one texel along `step` lands (its
// own stored depth, or this one's where it is empty).
float pixelsTo(ivec2 t, ivec2 step, float d, vec2 here) {
  ivec2 n = clamp(t + step, ivec2(0), ivec2(u_mapSize - 1));
  float dn = texelFetch(u_shadowMap, ivec3(n, 0), 0).r;
  vec4 c = u_eyeViewProj * vec4(sampleWorld(vec2(t + step) + 0.5, dn < 1.0 ? dn : d), 1.0);
  if (c.w <= 1e-6) return kMaxSplat;  // behind the eye: as large as allowed
  return length(c.xy / c.w * 0.5 * u_screenSize - here);
}

void main() {
  ivec2 t = ivec2(gl_VertexID % u_mapSize, gl_VertexID / u_mapSize);
  float d = texelFetch(u_shadowMap, ivec3(t, 0), 0).r;
  v_texel = vec2(t) + 0.5;
  if (!(d < 1.0)) {
    v_sample = vec3(0.0);
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: culled
    gl_PointSize = 1.0;
    return;
  }
  v_sample = sampleWorld(v_texel, d);
  gl_Position = u_eyeViewProj * vec4(v_sample, 1.0);
  gl_PointSize = u_forward_splat;
  if (u_forward_grow < 0.5) return;
  vec2 here = gl_Position.w > 1e-6 ? gl_Position.xy / gl_Position.w * 0.5 * u_screenSize : vec2(0.0);
  float footprint = max(max(pixelsTo(t, ivec2(1, 0), d, here), pixelsTo(t, ivec2(-1, 0), d, here)),
                        max(pixelsTo(t, ivec2(0, 1), d, here), pixelsTo(t, ivec2(0, -1), d, here)));
  // The splat is centred on the sample and must reach half a texel's footprint to each side (the
  // fragment test's forward.footprint texels wide); the diameter is the footprint times that.
  float size = footprint * u_forward_footprint + 1.0;
  gl_PointSize = clamp(isnan(size) ? kMaxSplat : size, u_forward_splat, kMaxSplat);
}
