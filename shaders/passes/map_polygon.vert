// A convex polygon of a map layer, u_polygon[0 .. n - 1] in uv, drawn as a triangle fan of n
// vertices: a fragment pass over the texels whose centres it covers (moment_filter.cpp: the
// texels visible receivers' lookups read).
const int kMaxPolygonCorners = 64;
uniform vec2 u_polygon[kMaxPolygonCorners];

void main() { gl_Position = vec4(2.0 * u_polygon[gl_VertexID] - 1.0, 0.0, 1.0); }
