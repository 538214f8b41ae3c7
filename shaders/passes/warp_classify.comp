// Sorts one instance's caster triangles for a warped light view (LogPSM) before the shadow pass
// draws them (logpsm.sort_casters): a triangle none of whose edges needs more than one piece
// goes to the plain list, drawn without tessellation stages; the others go to the patch list; one
// wholly beyond a side of the map goes to neither. passes/warp_levels.glsl decides, with the
// control stage's own corners, so each triangle is drawn as the tessellated pass alone would draw
// it: a patch whose levels are all 1 is its one triangle, interpolated (passes/warp_caster.glsl).
// Why: a software tessellator (llvmpipe) runs its stages patch by patch, whatever the levels.
layout(local_size_x = 64) in;
layout(std430) readonly buffer CasterVertices {
  float casterVertex[];  // 8 floats a vertex: position, normal, texture coordinate (render/gpu_scene.cpp)
};
layout(std430) readonly buffer CasterIndices {
  uint casterIndex[];
};
layout(std430) writeonly buffer SplitIndices {
  uint splitIndex[];
};
// Two DrawElementsIndirectCommands per instance (count, instances, first index, base vertex,
// base instance): its plain list, then its patch list; the counts start at 0.
layout(std430) buffer SplitCommands {
  uint splitCommand[];
};
uniform mat4 u_model;
uniform int u_triangles;
uniform int u_command;     // the instance's plain command, in uints
uniform int u_plainFirst;  // where its lists start in SplitIndices
uniform int u_patchFirst;
#include "passes/warp_levels.glsl"

// The corner's clip position as the vertex and control stages compute it (passes/shadow.vert,
// shadow_warp.tesc), the same operations in the same order.
vec4 cornerClip(uint index) {
  uint v = 8u * index;
  vec4 world = u_model * vec4(casterVertex[v], casterVertex[v + 1u], casterVertex[v + 2u], 1.0);
  return lightViewProjMatrix[u_shadowView] * vec4(world.xyz, 1.0);
}

void main() {
  uint triangle = gl_GlobalInvocationID.x;
  if (triangle >= uint(u_triangles)) return;
  uvec3 corner = uvec3(casterIndex[3u * triangle], casterIndex[3u * triangle + 1u], casterIndex[3u * triangle + 2u]);
  vec3 levels = warpEdgeLevels(cornerClip(corner.x), cornerClip(corner.y), cornerClip(corner.z), warpDeltaAndC());
  // GL discards a patch with a level that is not positive or is NaN; so does this pass.
  if (!all(greaterThan(levels, vec3(0.0)))) return;
  bool patches = max(levels.x, max(levels.y, levels.z)) > 1.0;
  uint command = uint(u_command) + (patches ? 5u : 0u);
  uint at = uint(patches ? u_patchFirst : u_plainFirst) + atomicAdd(splitCommand[command], 3u);
  splitIndex[at] = corner.x;
  splitIndex[at + 1u] = corner.y;
  splitIndex[at + 2u] = corner.z;
}
