// Caster patches of a dual-paraboloid map (layouts/dual_paraboloid.glsl): each edge is split finely
// enough that its chords stay within u_paraboloid_max_error texels of its image. The map is the
// stereographic projection of the directions from the light: a straight line's directions lie on
// a great circle, whose image is a circle of radius at least 1 (it meets the rim, the unit
// circle, at two opposite points), 1 / kParaboloidWindow in the map's [-1, 1] units. A piece of
// length l of a circle of curvature k errs by k l^2 / 8 at most, so a line of image length L
// needs L sqrt(k / (8 e)) pieces for an error e. A fitted window magnifies the disk by its zoom:
// image lengths grow by it and curvatures shrink by it (layouts/dual_paraboloid.glsl). The bound holds for every line, those inside the
// patch too (whose images the inner level splits); a tighter per-edge one (k = |n.z| for the
// plane's normal n) does not hold for the lines inside, and with a rigorous bound for those it
// saved no time on street (docs: techniques/point/README.md).
layout(vertices = 3) out;
in vec3 v_world[];
in vec2 v_uv[];
out vec3 tc_world[];
out vec2 tc_uv[];
uniform float u_paraboloid_max_error;

vec2 image(vec3 world) { return layoutClip(world).xy; }

float edgeLevel(vec3 a, vec3 b) {
  // Two chords through the image of the midpoint: a lower bound of the arc's length that the
  // single chord would miss for an arc bent by nearly a half turn.
  vec2 ia = image(a), ib = image(b), im = image(0.5 * (a + b));
  float len = length(im - ia) + length(ib - im);
  float errorNdc = 2.0 * u_paraboloid_max_error / u_shadowMapSize;
  // Zoomed unequally (zx > zy), a circle's image is an ellipse of largest curvature zx / zy^2
  // times the circle's: the bound takes zy^2 / zx for the zoom.
  vec2 z = paraboloidZooms(u_shadowView);
  float curvatureZoom = min(z.x, z.y) * min(z.x, z.y) / max(z.x, z.y);
  float pieces = len * sqrt(kParaboloidWindow / (curvatureZoom * 8.0 * errorNdc));
  return isnan(pieces) ? 64.0 : clamp(ceil(pieces), 1.0, 64.0);
}

void main() {
  tc_world[gl_InvocationID] = v_world[gl_InvocationID];
  tc_uv[gl_InvocationID] = v_uv[gl_InvocationID];
  if (gl_InvocationID != 0) return;
  if (!paraboloidViews()) {  // a focused matrix view: straight edges stay straight
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelInner[0] = 1.0;
    return;
  }
  // A triangle wholly behind the drawn hemisphere's margin (a convex cone of directions) is
  // dropped: an outer level of 0 discards the patch.
  if (layoutCullsCasterFragment(v_world[0]) && layoutCullsCasterFragment(v_world[1]) &&
      layoutCullsCasterFragment(v_world[2])) {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelInner[0] = 0.0;
    return;
  }
  // Outer level i is the edge opposite vertex i.
  gl_TessLevelOuter[0] = edgeLevel(v_world[1], v_world[2]);
  gl_TessLevelOuter[1] = edgeLevel(v_world[2], v_world[0]);
  gl_TessLevelOuter[2] = edgeLevel(v_world[0], v_world[1]);
  gl_TessLevelInner[0] = max(gl_TessLevelOuter[0], max(gl_TessLevelOuter[1], gl_TessLevelOuter[2]));
}
