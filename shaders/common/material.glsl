// Base colour and alpha mask shared by every pass that rasterizes the scene, so that
// alpha-tested casters cast the same holes they show. Variants come from defines
// (SL_TEXTURED, SL_ALPHA_MASK; see app/render/gpu_scene.h): opaque untextured surfaces fetch
// no texture and never discard.
uniform vec4 u_baseColor;
uniform float u_alphaCutoff;
#ifdef SL_TEXTURED
uniform sampler2D u_baseColorTexture;
#endif

vec4 materialColor(vec2 uv) {
#ifdef SL_TEXTURED
  return u_baseColor * texture(u_baseColorTexture, uv);
#else
  return u_baseColor;
#endif
}

void materialAlphaTest(vec2 uv) {
#ifdef SL_ALPHA_MASK
  if (materialColor(uv).a < u_alphaCutoff) discard;
#endif
}
