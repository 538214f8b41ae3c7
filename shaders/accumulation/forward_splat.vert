// One point per light-view sample (texel of view 0): its world position rebuilt from the depth
// the shadow pass stored (light-view linear depth over [near, far]), sent forward into the eye
// view. Empty texels (nothing rasterized: depth 1) send nothing.
uniform sampler2DArray u_shadowMap;  // the vertex stage gets only the layout module
uniform mat4 u_eyeViewProj;
uniform int u_mapSize;
uniform float u_forward_splat;
flat out vec3 v_sample;   // the sample's world position
flat out vec2 v_texel;    // its texel, in texels

void main() {
  ivec2 t = ivec2(gl_VertexID % u_mapSize, gl_VertexID / u_mapSize);
  float d = texelFetch(u_shadowMap, ivec3(t, 0), 0).r;
  v_texel = vec2(t) + 0.5;
  gl_PointSize = u_forward_splat;
  if (!(d < 1.0)) {
    v_sample = vec3(0.0);
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);  // outside the clip volume: culled
    return;
  }
  mat4 view = lightViewMatrix[0];
  mat4 proj = lightViewProjMatrix[0] * inverse(view);
  vec2 ndc = v_texel / float(u_mapSize) * 2.0 - 1.0;
  vec4 ray = inverse(proj) * vec4(ndc, 0.0, 1.0);
  ray /= ray.w;
  float z = lightViewRange[0].x + d * (lightViewRange[0].y - lightViewRange[0].x);
  // Perspective view (spot light): along the texel's ray to that view distance; orthographic:
  // straight down the view axis.
  vec3 p = lightViewRange[0].w > 0.5 ? ray.xyz * (z / max(-ray.z, 1e-9)) : vec3(ray.xy, -z);
  v_sample = (inverse(view) * vec4(p, 1.0)).xyz;
  gl_Position = u_eyeViewProj * vec4(v_sample, 1.0);
}
