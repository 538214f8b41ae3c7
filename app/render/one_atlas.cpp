// One atlas for every light's map (lights.one_atlas; beyond the papers: the shadow atlas engines
// shade many lights from). The texel budget sizes each light's map by the screen its range
// covers (render/light_budget.h); here those maps become regions of one depth layer, packed
// bottom-left into the smallest square that holds them (packAtlasRegions), the room left given
// to the lights by the budget's own rule (fillAtlasSizes, before the sizes are handed out), and
// each light's layout's views are moved into its region
// (placeInAtlasRegion). Inside a region a layout keeps its own packing: cube-atlas's faces by
// need. A light draws only its region (the shadow pass clears it alone) and its lookups stay in
// it (lightViewTap), so the lights' parts still know nothing of each other.
#include "render/light_budget.h"
#include "render/renderer.h"

namespace sl {

bool Renderer::canJoinOneAtlas(const Viewport& light, const LightDemand& demand) const {
  // One layer (an atlas of faces, a focused map: the budget's count, Renderer::lightLayerCount),
  // drawn whole, by a plain depth map.
  return demand.footprint > 0.0 && demand.layers == 1 && light.layout->drawsWholeViews() &&
         light.representation->canShareDepthLayer();
}

void Renderer::assignOneAtlas(Viewport& vp, const std::vector<Viewport*>& lights, const std::vector<int>& asked) {
  // Every light leaves the layer first (its state may point at a layer about to be replaced);
  // the ones drawn this frame join it again when their views are placed.
  for (Viewport* light : lights) {
    light->representation->shareDepthLayer(nullptr);
    light->inOneAtlas_ = false;
  }
  const AtlasRegions regions = packAtlasRegions(asked);
  if (regions.side == 0) {
    vp.oneAtlas_.reset();
  } else if (!vp.oneAtlas_ || vp.oneAtlas_->layer.size != regions.side) {
    auto atlas = std::make_unique<OneAtlas>();
    atlas->depth =
        Texture2D::array(GL_DEPTH_COMPONENT32F, regions.side, regions.side, 1, 1, "one atlas of every light's maps");
    atlas->framebuffer = Framebuffer("one atlas of every light's maps");
    atlas->framebuffer.attachLayer({}, &atlas->depth, 0);
    // Cleared once: a region is cleared when its light draws, the gaps never (the debug view).
    glClearNamedFramebufferfi(atlas->framebuffer.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
    atlas->layer = {&atlas->depth, &atlas->framebuffer, regions.side};
    vp.oneAtlas_ = std::move(atlas);
  }
  for (size_t k = 0; k < lights.size(); ++k) {
    lights[k]->atlasRegion_ = regions.rects[k];
    lights[k]->oneAtlasLayer_ = regions.rects[k].z > 0 ? &vp.oneAtlas_->layer : nullptr;
  }
}

void Renderer::placeInOneAtlas(Viewport& light) {
  const SharedDepthLayer* layer = light.oneAtlasLayer_;
  // A region is given only to a light that can join (canJoinOneAtlas); its views must still fit.
  light.inOneAtlas_ =
      layer && light.atlasRegion_.z > 0 && placeInAtlasRegion(light.lightSpace, light.atlasRegion_, layer->size);
  light.representation->shareDepthLayer(light.inOneAtlas_ ? layer : nullptr);
  // Drawn elsewhere than last frame (another region, another layer, or in or out of the atlas):
  // what the layout kept of earlier frames (faces cached in the old place) is forgotten.
  const glm::ivec4 placed = light.inOneAtlas_ ? light.atlasRegion_ : glm::ivec4(0);
  const int side = light.inOneAtlas_ ? layer->size : 0;
  if (placed != light.placedRegion_ || side != light.placedAtlasSide_) {
    light.layout->reset();
    light.placedRegion_ = placed;
    light.placedAtlasSide_ = side;
  }
}

}  // namespace sl
