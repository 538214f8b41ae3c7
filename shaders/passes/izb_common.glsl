// Buffers and helpers shared by the irregular z-buffer passes (techniques/irregular/). Binding
// numbers are fixed here and in izb_state.cpp (kBind*): storage buffers have no allocator.
// Only the blocks a pass uses are active in its program.

struct Triangle {  // world space; w: instance + 1, triangle in its mesh, material (as bits)
  vec4 a, b, c;
  vec4 uv01;
  vec4 uv2;
};
struct Material {
  uvec4 texture;  // alpha byte offset, width, height, masked
  vec4 alpha;     // cutoff, base colour alpha
};

layout(std430) readonly buffer IzbTriangles { Triangle triangles[]; };
layout(std430) readonly buffer IzbInstanceBase { uint instanceBase[]; };
layout(std430) readonly buffer IzbMaterials { Material materials[]; };
layout(std430) readonly buffer IzbAlpha { uint alphaBytes[]; };
layout(std430) buffer IzbCounts { uint counts[]; };       // samples per cell
layout(std430) buffer IzbOffsets { uint offsets[]; };     // exclusive prefix sum, cells + 1
layout(std430) buffer IzbBlockSums { uint blockSums[]; }; // per 1024 cells
// Each pixel's sample: x its cell, y its own triangle (global index), never its occluder.
layout(std430) buffer IzbPixelCell { uvec2 pixelCell[]; };
// Each pixel's ray (kSampleVec4s a pixel): its start on its own triangle's plane, w: tnear (the
// height tolerance); under a light with a position then its direction to the light's centre,
// w: tfar. A sun's rays all go along -u_lightDirection, to infinity: 16 bytes a sample, not 48.
layout(std430) buffer IzbSamples { vec4 samples[]; };
#ifdef IZB_POSITIONAL  // defined (0 or 1) by the passes that write or read the rays
const uint kSampleVec4s = IZB_POSITIONAL != 0 ? 2u : 1u;
#endif
layout(std430) buffer IzbList { uint list[]; };           // pixel indices, by cell
// Four words per cell (kCellWords): [0] the farthest of its samples from the light (orderedBits
// of izbAwayKey, 0 when empty), [1] how many of its samples a triangle has occluded (when all,
// the cell is done), [2] the one triangle all its samples lie on (its index + 1; 0 none yet,
// kMixedOwners several or unknown), [3] unused. One block: every block a program declares
// counts against the 16 a compute shader may have, used or not.
layout(std430) buffer IzbCellState { uint cellState[]; };
const uint kCellWords = 4u;
const uint kMixedOwners = 0xffffffffu;
layout(std430) buffer IzbBits { uint shadowBits[]; };    // 1 = occluded
layout(std430) buffer IzbFallback { uint fallbackBits[]; };  // 1 = not listed: map test
// 0: overflowed, 1: listed, 2: rows of triangles without an alpha mask queued, 3: ~bits of the
// least listed clip w, 4: bits of the greatest (w > 0: a positive float's bits order as it
// does), 5: rows of alpha-masked triangles queued
layout(std430) buffer IzbCounters { uint counters[]; };

uniform int u_izbGrid;      // cells per side
uniform vec2 u_izbSize;     // eye samples: the viewport's pixels (whole numbers)
uniform int u_izbCapacity;  // entries of the list buffer
uniform mat4 u_izbViewProj; // the layout's light view: where cells are
// The sign of the grid view's depth (clip z / w) along a ray toward the light (izb_state.cpp).
uniform float u_izbDepthTowardLight;

const uint kNoCell = 0xffffffffu;

// Grid coordinates (cells, fractional) of a clip-space point in front of the view (w > 0).
vec2 izbGridOf(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * float(u_izbGrid); }

// Grid coordinates (cells, fractional) of a world point and its clip w; false behind a
// perspective light.
bool izbGridPos(vec3 p, out vec2 g, out float w) {
  vec4 c = u_izbViewProj * vec4(p, 1.0);
  g = vec2(0.0);
  w = c.w;
  if (!(c.w > 1e-6)) return false;
  g = izbGridOf(c);
  return !any(isnan(g));
}

// A key that grows with the distance from the light along every sample's ray (monotonic in the
// view's depth, clip z / w, which is linear along a ray that projects to one point and across a
// triangle wholly in front of the view): a caster nearer the light than a sample has a smaller
// key, so a triangle whose smallest key exceeds a cell's farthest sample hits none of them.
float izbAwayKey(vec4 clip) { return -u_izbDepthTowardLight * clip.z / clip.w; }

// Clamped to the grid: a point outside it is listed under the border cell, where every
// triangle covering it also lands (the clamp of a triangle's bounds holds the clamped point).
ivec2 izbCell(vec2 g) { return ivec2(clamp(floor(g), vec2(0.0), vec2(float(u_izbGrid - 1)))); }
