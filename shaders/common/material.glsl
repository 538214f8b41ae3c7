// Base colour and alpha mask shared by every pass that rasterizes the scene, so that
// alpha-tested casters cast the same holes they show.
uniform vec4 u_baseColor;
uniform sampler2D u_baseColorTexture;
uniform float u_hasTexture;
uniform float u_alphaMask;
uniform float u_alphaCutoff;

vec4 materialColor(vec2 uv) {
  vec4 c = u_baseColor;
  if (u_hasTexture > 0.5) c *= texture(u_baseColorTexture, uv);
  return c;
}

void materialAlphaTest(vec2 uv) {
  if (u_alphaMask > 0.5 && materialColor(uv).a < u_alphaCutoff) discard;
}
