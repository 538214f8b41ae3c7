// Debug views of the virtual shadow map (SL_VIRTUAL_VIEW from the layout state):
// 0 `pages`: the level of the page each pixel reads (virtualLevelColour: 0 red, 1 orange,
//   2 yellow, 3 green, 4 cyan, 5 blue, 6 purple, 7+ grey), page borders dark, hatched where the
//   page is coarser than the pixel asked for (pool exhausted);
// 1 `requested-resolution`: the level the pixel asked for under virtual.criterion (the marking
//   pass's own function, layouts/virtual_request.glsl), same colours;
// 2 `cache`: red = page drawn this frame, green = served from the cache (brighter: more frames).
#include "common/light.glsl"
#include "layouts/virtual_request.glsl"
uniform sampler2D u_gPosition;
uniform sampler2D u_gNormal;
out vec4 o_color;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(u_gPosition, pixel, 0);
  if (P.w < 0.5) {
    o_color = vec4(0.1, 0.1, 0.12, 1.0);
    return;
  }
  vec3 N = normalize(texelFetch(u_gNormal, pixel, 0).xyz);
  float shade = 0.45 + 0.55 * max(dot(N, directionToLight(P.xyz)), 0.0);
  vec2 uv;
  int requested = virtualRequestedLevel(u_gPosition, pixel, uv);
  VirtualPage page;
  bool onMap = requested >= 0;
  vec3 colour = vec3(0.3);
#if SL_VIRTUAL_VIEW == 1
  if (onMap) colour = virtualLevelColour(requested);
#else
  if (onMap && virtualFindPage(uv, page)) {
#if SL_VIRTUAL_VIEW == 0
    colour = virtualLevelColour(page.level);
    if (page.level > requested && mod(gl_FragCoord.x + gl_FragCoord.y, 6.0) < 2.0)
      colour *= 0.4;
#else
    float hits = float(page.entry >> 24);
    colour = (page.entry & (1u << 16)) != 0u ? vec3(0.9, 0.2, 0.2)
                                              : vec3(0.15, 0.35, 0.15) + vec3(0.1, 0.6, 0.1) * min(hits / 30.0, 1.0);
#endif
    // Page borders: the local position's screen-space change shows how wide a line is.
    vec2 edge = min(page.local, 1.0 - page.local) / max(fwidth(page.local), vec2(1e-6));
    if (min(edge.x, edge.y) < 1.0) colour *= 0.3;
  }
#endif
  o_color = vec4(pow(colour * shade, vec3(1.0 / 2.2)), 1.0);
}
