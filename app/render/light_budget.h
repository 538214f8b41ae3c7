// Which lights of a scene of several a frame makes maps for, and how large (beyond the papers:
// the survey's "one texel per pixel" applied across lights). A light whose reach (its range, the
// scene's bounds) shows no visible point lights no pixel of this frame: it is not drawn, exactly.
// The others share a texel budget (lights.texel_budget) in proportion to the screen they cover,
// each light's maps on a ladder of halvings of shadowmap.size so that a size changes seldom.
// Pure geometry and arithmetic (no GL): tests/light_budget_test.cpp.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>
#include <vector>

namespace sl {

// The fraction of the screen (0..1) covered by the projection of the light's reach (the box
// around a point light's range, else the scene's bounds) clipped by the camera frustum and the
// scene's bounds: its convex hull, so an upper bound of the pixels the light can reach. 0 when
// that body is empty (no visible point is in its range).
// ndcBounds (when given): the hull's bounding rectangle in normalized device coordinates, min xy
// and max xy, within [-1, 1] (the whole screen when the footprint is 0).
double lightFootprint(const Light& light, const Bounds& sceneBounds, const glm::mat4& view, const glm::mat4& proj,
                      glm::vec4* ndcBounds = nullptr);

// The pixels (x, y, width, height) a light of limited reach (a point light with a range) can
// light: ndcBounds in a width x height frame, widened by a pixel for rounding; the whole frame
// for a light of unlimited reach.
glm::ivec4 lightScissor(const Light& light, const glm::vec4& ndcBounds, int width, int height);

// The footprint a light's budget uses this frame, given the one it used last frame (`held`)
// and the one measured now: the held one while now stays within a factor `band` of it, so a
// camera hovering where the allocation steps does not switch a lamp's maps back and forth every
// frame (each switch re-allocates them). 0 (reaching nothing in view: not drawn, which must be
// exact) and the first measure after 0 pass at once.
double heldFootprint(double held, double now, double band = 1.5);

struct LightDemand {
  double footprint = 1.0;  // lightFootprint; 0 = not drawn
  int layers = 1;          // layers of the light's maps (a cube: 6; an atlas of its faces: 1)
};

// Texels per side of each light's maps: 0 for a light of no footprint, else maxSize >> j. With
// budgetTexels <= 0 every drawn light gets maxSize. Otherwise every drawn light starts at the
// smallest step of at least minSize, and the light with the most footprint per texel is doubled
// while the sum of layers · size² stays within the budget: a light of more footprint never gets
// fewer texels per view than one of less, and the sum exceeds the budget only when the smallest
// steps alone do.
std::vector<int> budgetMapSizes(const std::vector<LightDemand>& lights, double budgetTexels, int maxSize, int minSize);

// The sum of layers · size² of those sizes.
double budgetedTexels(const std::vector<LightDemand>& lights, const std::vector<int>& sizes);

// Every light's map in one atlas layer (lights.one_atlas; beyond the papers: the shadow atlas of
// engines that shade many lights from one texture): squares of the given sides (0: none), largest
// first, each at the lowest then leftmost place on a skyline (bottom-left packing), in the
// smallest square layer that holds them, searched from the side of their total area upward in
// steps of 1/64 (sides multiples of 8). side 0: no square asked.
struct AtlasRegions {
  int side = 0;                   // texels per side of the atlas layer
  std::vector<glm::ivec4> rects;  // per entry x, y, width, height in texels (0: none asked)
};
AtlasRegions packAtlasRegions(const std::vector<int>& sides);

// Larger shared layers are not made (256 MB of 32-bit depth): the lights keep maps of their own.
constexpr int kMaxOneAtlasSide = 8192;

// The budget's sizes with those of the lights in one atlas (inAtlas[k]) grown into the room left
// in the square packAtlasRegions makes for them: the light with the most footprint per texel
// goes a step up the ladder while they all still pack into a square of that side, none beyond
// the largest.
// The atlas's texels are allocated whatever the lights draw into them; the others are unchanged.
// When that square would be over kMaxOneAtlasSide, none is in the atlas (inAtlas cleared).
std::vector<int> fillAtlasSizes(const std::vector<LightDemand>& lights, std::vector<int> sizes,
                                std::vector<bool>& inAtlas);

}  // namespace sl
