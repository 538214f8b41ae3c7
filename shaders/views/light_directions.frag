// The `directions` view of the point-light layouts (techniques/point/directions_view.cpp): every
// direction from the light, as a latitude-longitude panorama (x: azimuth -180..180 degrees,
// y: elevation -90..90), tinted by the light view (face, hemisphere) a point in that direction
// reads, shaded by the depth stored there (near = bright). Directions outside every fitted window
// are dark grey; a cleared texel (nothing drawn, an undrawn face included) is hatched. Where a
// texel spans three or more pixels its grid is drawn: the map's density over the sphere.
#include "common/light.glsl"
uniform sampler2DArray u_shadowDepth;
uniform vec2 u_viewSize;
out vec4 o_color;

const vec3 kViewTints[6] = vec3[6](vec3(0.90, 0.30, 0.25), vec3(0.95, 0.75, 0.20), vec3(0.35, 0.75, 0.30),
                                   vec3(0.25, 0.55, 0.90), vec3(0.65, 0.40, 0.85), vec3(0.30, 0.80, 0.80));

void main() {
  vec2 t = gl_FragCoord.xy / u_viewSize;
  float azimuth = (t.x * 2.0 - 1.0) * 3.14159265, elevation = (t.y - 0.5) * 3.14159265;
  vec3 d = vec3(cos(elevation) * cos(azimuth), sin(elevation), cos(elevation) * sin(azimuth));
  ShadowCoord c = layoutShadowCoord(u_lightPosition + d);
  vec3 tint = kViewTints[clamp(c.view, 0, 5)];
  if (c.view < 0 || any(lessThan(c.uv, vec2(0.0))) || any(greaterThan(c.uv, vec2(1.0)))) {
    o_color = vec4(mix(vec3(0.18), tint, 0.15), 1.0);  // no texel of any window holds it
    return;
  }
  vec2 size = vec2(textureSize(u_shadowDepth, 0).xy);
  float stored = texture(u_shadowDepth, vec3(c.uv, lightViewLayer(c.view))).r;
  vec3 colour;
  if (stored >= 1.0) {
    float hatch = step(0.5, fract((gl_FragCoord.x + gl_FragCoord.y) / 8.0));
    colour = mix(vec3(0.05), tint * 0.5, hatch);  // cleared: nothing drawn there
  } else {
    // Stored depth is linear over [near, far]; a square root spreads the near range a lamp lights.
    colour = tint * (1.0 - 0.75 * sqrt(clamp(stored, 0.0, 1.0)));
  }
  vec2 texel = c.uv * size;
  vec2 perPixel = fwidth(texel);
  if (max(perPixel.x, perPixel.y) < 0.33) {  // a texel at least three pixels wide: show its edges
    vec2 toEdgePixels = (0.5 - abs(fract(texel) - 0.5)) / max(perPixel, vec2(1e-6));
    if (min(toEdgePixels.x, toEdgePixels.y) < 1.0) colour = mix(colour, vec3(1.0), 0.35);
  }
  o_color = vec4(colour, 1.0);
}
