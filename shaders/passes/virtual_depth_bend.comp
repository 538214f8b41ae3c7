// The tiled maps' depth-discontinuity term, per texel of the virtual atlas's tiles drawn since
// the last marking (techniques/adaptive/depth_bend.h): the largest second difference of the
// light's depth along the rows, columns and diagonals of the 3x3 texels around the texel, the
// centre kept one texel inside its page (a page's border texels take their inner neighbour's).
// The marking pass compares it with virtual.depth_step (layouts/virtual_request.glsl).
// Defines: the virtual layout's (SL_VIRTUAL_PAGE, SL_VIRTUAL_POOL_SIDE).
layout(local_size_x = 16, local_size_y = 16) in;
uniform sampler2DArray u_virtualDepthAtlas;
layout(r32f) uniform writeonly image2D u_virtualDepthBend;
layout(std430) buffer BendTiles { int bendTiles[]; };

void main() {
  ivec2 local = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(local, ivec2(SL_VIRTUAL_PAGE)))) return;
  int tile = bendTiles[gl_WorkGroupID.z];
  ivec2 origin = ivec2(tile % SL_VIRTUAL_POOL_SIDE, tile / SL_VIRTUAL_POOL_SIDE) * SL_VIRTUAL_PAGE;
  ivec2 centre = clamp(local, ivec2(1), ivec2(SL_VIRTUAL_PAGE - 2));
  float d[9];
  for (int k = 0; k < 9; ++k)
    d[k] = texelFetch(u_virtualDepthAtlas, ivec3(origin + centre + ivec2(k % 3 - 1, k / 3 - 1), 0), 0).r;
  float bend = max(max(abs(d[3] + d[5] - 2.0 * d[4]), abs(d[1] + d[7] - 2.0 * d[4])),
                   max(abs(d[0] + d[8] - 2.0 * d[4]), abs(d[2] + d[6] - 2.0 * d[4])));
  imageStore(u_virtualDepthBend, origin + local, vec4(bend));
}
