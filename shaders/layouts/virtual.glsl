// Layout module of the paged virtual shadow map (Lefohn et al. 2007): one orthographic (or spot)
// light view over the whole scene at virtual.size texels per side, stored as pages of a mip
// pyramid in the tiles of one physical atlas. The page table (R32UI, a mip level per page level;
// techniques/adaptive/page_allocator.h) maps a page to its tile; a lookup takes the finest
// resident page, so a point whose page is missing (pool exhausted) reads a coarser one.
// layoutShadowCoord returns atlas uv, so the representations' depth tests run unchanged.
#include "layouts/virtual_common.glsl"
#define SL_LAYOUT_DEPTH_AFFINE  // layoutDepth: light-view linear depth (passes/caster_depth.glsl)
uniform float u_shadowMapSize;  // atlas texels per side
uniform int u_shadowView;
uniform vec4 u_pageTransform;  // shadow pass: clip xy * .xy + w * .zw maps one page to the viewport

vec4 layoutClipIn(vec3 worldPos, int view) { return lightViewProjMatrix[0] * vec4(worldPos, 1.0); }

float layoutDepthIn(vec3 worldPos, int view) {
  float z = -(lightViewMatrix[0] * vec4(worldPos, 1.0)).z;
  return (z - lightViewRange[0].x) / (lightViewRange[0].y - lightViewRange[0].x);
}

vec4 layoutClip(vec3 worldPos) {
  vec4 c = layoutClipIn(worldPos, 0);
  c.xy = c.xy * u_pageTransform.xy + u_pageTransform.zw * c.w;
  return c;
}
float layoutDepth(vec3 worldPos) { return layoutDepthIn(worldPos, 0); }

ShadowCoord layoutShadowCoordIn(vec3 worldPos, int view) {
  vec4 c = layoutClipIn(worldPos, 0);
  if (!(c.w > 1e-6)) return shadowCoordNone();
#ifdef SL_PERSPECTIVE_MAP
  float depth = layoutDepthIn(worldPos, 0);
#else
  float depth = c.z * 0.5 + 0.5;
#endif
  vec2 uv = c.xy / c.w * 0.5 + 0.5;
  VirtualPage page;
  // Off the map, or no page at all: uv outside [0,1] reads as lit (no caster was rendered).
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || !virtualFindPage(uv, page))
    return ShadowCoord(vec2(-1.0), depth, 0, -1, 0.0);
  // Texel centres of the page only: a filter must not read the neighbouring tile.
  float halfTexel = 0.5 / float(SL_VIRTUAL_PAGE);
  vec2 local = clamp(page.local, vec2(halfTexel), vec2(1.0 - halfTexel));
  vec2 tile = vec2(page.tile % SL_VIRTUAL_POOL_SIDE, page.tile / SL_VIRTUAL_POOL_SIDE);
  return ShadowCoord((tile + local) / float(SL_VIRTUAL_POOL_SIDE), depth, 0, -1, 0.0);
}

ShadowCoord layoutShadowCoord(vec3 worldPos) { return layoutShadowCoordIn(worldPos, 0); }

// Texel world size of the page that serves the point: level-0 size times 2^level (times the
// light distance for a spot's perspective map, as LightView::texelWorldSize says).
float layoutTexelWorldSize(vec3 worldPos, int view) {
  vec3 uv = virtualUv(worldPos);
  VirtualPage page;
  float level = uv.z != 0.0 && virtualFindPage(clamp(uv.xy, vec2(0.0), vec2(1.0)), page) ? float(page.level) : 0.0;
  float size = lightViewRange[0].z * exp2(level);
#ifdef SL_PERSPECTIVE_MAP
  size *= max(-(lightViewMatrix[0] * vec4(worldPos, 1.0)).z, 1e-4);
#endif
  return size;
}

float layoutDepthScale(int view) { return 1.0 / (lightViewRange[0].y - lightViewRange[0].x); }
