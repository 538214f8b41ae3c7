// What the one generic shadow pass draws for a viewport: the caster stages, which casters, and
// per light view the whole layer or only some tiles of it. The layout (its light views' projection
// kind, its tiles) and the representation (its fragment stage, which casters it takes) fill it in
// as data; the renderer draws it. No GL calls here, so plans are tested without a GPU.
#pragma once

#include "part/light_space.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <string>
#include <utility>
#include <vector>

namespace sl {

// Which instances the shadow pass draws: Opaque when the representation takes the
// semi-transparent ones in passes of its own (deep shadow maps' fragment lists).
enum class CasterSet { All, Opaque };

// A representation's part of the plan.
struct CasterDraw {
  std::string fragment = "passes/shadow.frag";  // moment representations write their own targets
  CasterSet casters = CasterSet::All;
};

// A piece of a layer drawn into its own rectangle (a page of a virtual map).
struct ShadowTile {
  glm::ivec4 rect{0};  // x, y, width, height in texels of the layer: viewport, scissor, the part cleared
  // u_pageTransform: clip xy * .xy + clip w * .zw maps the tile's square of the layer's clip
  // space onto the rectangle (identity: (1, 1, 0, 0)).
  glm::vec4 transform{1.0f, 1.0f, 0.0f, 0.0f};
  // The viewport is the whole layer rather than the rectangle (an atlas view's projection places
  // it in the rectangle itself); the rectangle still scissors and clears.
  bool wholeLayerViewport = false;
  // The same as a matrix after the layer's view-projection, so instances outside the tile are
  // skipped (shadowmap.cull_instances).
  glm::mat4 clip(const glm::mat4& layerViewProj) const;
};

// The tile that draws a view of an atlas (LightView::atlasRect): its view-projection already
// maps it into its rectangle of the layer, so the viewport is the whole layer and the rectangle
// only scissors and clears.
ShadowTile atlasTile(const glm::ivec4& rect);

struct ShadowLayerDraw {
  bool tiled = false;             // false: the whole layer, cleared first
  std::vector<ShadowTile> tiles;  // tiled: only these, each cleared; the rest of the layer is kept
};

struct ShadowDrawPlan {
  std::vector<std::pair<GLenum, std::string>> stages;
  // A compute stage that sorts each instance's triangles into those the tessellation stages
  // must cut and those drawn without them (empty: every triangle goes through `stages`).
  std::string sortStage;
  CasterSet casters = CasterSet::All;
  std::vector<ShadowLayerDraw> layers;  // one per light view
};

// The stages that draw casters into the light views: passes/shadow.vert, the tessellation
// stages when a view is not a projective map (LightView::Projection::LogWarp and ::Paraboloid
// bend straight edges), then `fragment`.
std::vector<std::pair<GLenum, std::string>> casterStages(const LightSpace& lightSpace, const std::string& fragment);
// The sorting stage for those stages: passes/warp_classify.comp where a LogWarp view asks for it
// (LightView::sortCasters); none otherwise.
std::string casterSortStage(const LightSpace& lightSpace);
// `stages` without their tessellation stages: how the sorted plain triangles are drawn.
std::vector<std::pair<GLenum, std::string>> withoutTessellation(std::vector<std::pair<GLenum, std::string>> stages);

}  // namespace sl
