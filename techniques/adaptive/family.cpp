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

// The page levels' colours (virtualLevelColour() in shaders/layouts/virtual_common.glsl), then the
// view's own grey and the sky.
std::vector<SpecialColour> levelColours(const std::string& greyMeaning) {
  return {{{0.90f, 0.25f, 0.20f}, "red: level 0 (finest, virtual.size texels)"},
          {{0.95f, 0.60f, 0.20f}, "orange: level 1 (texels 2x larger)"},
          {{0.95f, 0.90f, 0.30f}, "yellow: level 2 (4x)"},
          {{0.35f, 0.80f, 0.30f}, "green: level 3 (8x)"},
          {{0.30f, 0.80f, 0.85f}, "cyan: level 4 (16x)"},
          {{0.25f, 0.45f, 0.95f}, "blue: level 5 (32x)"},
          {{0.65f, 0.40f, 0.85f}, "purple: level 6 (64x)"},
          {{0.60f, 0.60f, 0.60f}, "light grey: level 7 or coarser"},
          {{0.30f, 0.30f, 0.30f}, "dark grey: " + greyMeaning},
          {{0.10f, 0.10f, 0.12f}, "near-black: no geometry (sky)"}};
}

// The virtual map's views (shaders/views/virtual.frag, SL_VIRTUAL_VIEW 0, 1, 2): the page level a
// pixel reads or asks for (its level from shaders/layouts/virtual_request.glsl), and the page cache.
void addVirtualViewKeys(std::map<std::string, ColourKey>& keys) {
  keys["pages"] = {"virtual-map page level each pixel reads (0 = finest)",
                   "",
                   {},
                   levelColours("off the map, or no resident page"),
                   "shaded (N.L, gamma 2.2); dark lines: page edges; hatched: coarser than asked"};
  keys["requested-resolution"] = {"page level each pixel asks for (virtual.criterion)",
                                  "",
                                  {},
                                  levelColours("off the map (asks for no page)"),
                                  "the marking pass's own level (with virtual.lod_bias); shaded (N.L, gamma 2.2)"};
  keys["cache"] = {"frames each page has been served from the cache",
                   "frames",
                   {{0.0f, {0.15f, 0.35f, 0.15f}, "0 frames"},
                    {0.5f, {0.20f, 0.65f, 0.20f}, "15 frames"},
                    {1.0f, {0.25f, 0.95f, 0.25f}, "30+ frames"}},
                   {{{0.90f, 0.20f, 0.20f}, "red: page drawn this frame (cache miss)"},
                    {{0.30f, 0.30f, 0.30f}, "dark grey: off the map, or no resident page"},
                    {{0.10f, 0.10f, 0.12f}, "near-black: no geometry (sky)"}},
                   "restarts when the page is redrawn; shaded (N.L, gamma 2.2); dark lines: edges"};
}

}  // namespace

Family adaptiveFamily() {
  Family f{.id = "adaptive",
           .summary =
               "adaptive sampling: a paged virtual shadow map whose pages are chosen by the visible pixels (Lefohn et "
               "al. 2007, Fernando et al. 2001, Giegl & Wimmer 2007)"};
  registerAdaptiveLayouts(f.layouts);
  addVirtualPresets(f.presets);
  addVirtualViewKeys(f.viewKeys);
  return f;
}

}  // namespace sl
