// The adaptive family's manifest: its parts and presets (registry.cpp lists the families).
#include "adaptive/virtual_layout.h"
#include "part/family.h"

namespace sl {

namespace {

// The virtual map's pages under each page criterion.
void addVirtualPresets(std::vector<Preset>& v) {
  v.insert(
      v.end(),
      {
          {"virtual",
           "paged virtual shadow map (Lefohn et al. 2007): 16384² virtual texels over the scene, only the pages and "
           "mip "
           "levels the visible pixels need, in one 1920² atlas, cached while nothing moves; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {}},
          {"tiled",
           "the virtual map's pages chosen by a distance heuristic (after Arvo 2004, tiled shadow maps): each pixel's "
           "world size decides its level, the atlas is the texel budget; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {"virtual.criterion=distance"}},
          {"adaptive",
           "adaptive shadow maps over the virtual map's pages (Fernando et al. 2001, Lefohn et al. 2006): full "
           "resolution only near last frame's shadow edges, 3 levels coarser elsewhere; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {"virtual.criterion=edges"}},
          {"fitted-virtual",
           "fitted virtual shadow maps (Giegl & Wimmer 2007) over the virtual map's pages: the pixels' footprints "
           "gathered into a grid over the light's view, read back and fitted into a quadtree on the CPU, whose leaves "
           "are the pages drawn; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {"virtual.criterion=fitted"}},
      });
}

}  // namespace

Family adaptiveFamily() {
  Family f{.id = "adaptive",
           .summary =
               "adaptive sampling: a paged virtual shadow map whose pages are chosen by the visible pixels (Lefohn et "
               "al. 2007, Fernando et al. 2001, Giegl & Wimmer 2007)"};
  registerAdaptiveLayouts(f.layouts);
  addVirtualPresets(f.presets);
  return f;
}

}  // namespace sl
