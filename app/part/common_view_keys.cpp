#include "part/common_view_keys.h"

#include <algorithm>
#include <map>

namespace sl {

namespace {

// Background of the views that read the G-buffer (no geometry there).
const SpecialColour kSky{{0.10f, 0.10f, 0.12f}, "no geometry (sky)"};
const SpecialColour kBlackSky{{0.0f, 0.0f, 0.0f}, "black: no geometry (sky)"};

// The views of any shadow map: texel density, depth, the shadow term and the texel grid.
void addShadowMapKeys(std::map<std::string, ColourKey>& keys) {
  // shaders/views/aliasing.frag: aliasingHeat().
  keys["aliasing"] = {"screen pixels per shadow-map texel",
                      "px/texel",
                      {{0.0f, {0.10f, 0.30f, 1.00f}, "1/4096"},
                       {0.25f, {0.10f, 0.75f, 0.90f}, "1/64"},
                       {0.5f, {0.10f, 0.80f, 0.20f}, "1"},
                       {0.75f, {0.95f, 0.85f, 0.10f}, "64"},
                       {1.0f, {1.00f, 0.10f, 0.05f}, "4096"}},
                      {kSky},
                      "log scale: red = blocky (undersampled), blue = texels wasted"};
  // shaders/views/shadowmap.frag: normalised to the depths present in each layer.
  keys["shadowmap"] = {"light-space depth (per layer, stretched to its min..max)",
                       "",
                       {{0.0f, {1.0f, 1.0f, 1.0f}, "near"}, {1.0f, {0.1f, 0.1f, 0.1f}, "far"}},
                       {{{0.0f, 0.0f, 0.0f}, "black: empty (cleared, nothing drawn)"}},
                       ""};
  keys["visibility"] = {"visibility (shadow term)",
                        "",
                        {{0.0f, {0.0f, 0.0f, 0.0f}, "0 shadow"}, {1.0f, {1.0f, 1.0f, 1.0f}, "1 lit"}},
                        {{{1.0f, 0.0f, 1.0f}, "magenta: NaN/Inf"}, {{0.2f, 0.2f, 0.25f}, "no geometry"}},
                        ""};
  keys["texels"] = {"shadow-map texels (checkerboard)",
                    "",
                    {},
                    {{{0.95f, 0.75f, 0.30f}, "even texel"},
                     {{0.25f, 0.35f, 0.75f}, "odd texel"},
                     {{0.62f, 0.55f, 0.52f}, "texel < 2 px: averaged"},
                     {{0.30f, 0.30f, 0.30f}, "outside the map"},
                     kSky},
                    "big squares = one texel over many pixels"};
}

// The light-space overview and the error view: categories only, no gradient.
void addOverviewKeys(std::map<std::string, ColourKey>& keys) {
  // app/render/debug_views.cpp: the lightspace overview's line colours.
  keys["lightspace"] = {"overview: camera and light frusta",
                        "",
                        {},
                        {{{1.0f, 0.85f, 0.1f}, "yellow: camera frustum"},
                         {{0.2f, 0.9f, 1.0f}, "cyan: light view"},
                         {{1.0f, 1.0f, 1.0f}, "white: camera (with cascades)"},
                         {{0.90f, 0.30f, 0.25f}, "red, yellow, green..: cascades"}},
                        ""};
  // app/metrics/metrics.cpp: errorImage().
  keys["error"] = {"difference to the ray-traced reference",
                   "",
                   {},
                   {{{0.5f, 0.5f, 0.5f}, "grey: agrees (reference, half bright)"},
                    {{0.90f, 0.47f, 0.0f}, "orange: false shadow"},
                    {{0.16f, 0.47f, 1.0f}, "blue: false light"},
                    {{1.0f, 0.0f, 1.0f}, "magenta: NaN/Inf"},
                    {{0.0f, 0.0f, 0.0f}, "black: no geometry / no reference"}},
                   "needs a resting camera"};
}

std::map<std::string, ColourKey> makeKeys() {
  std::map<std::string, ColourKey> keys;
  addShadowMapKeys(keys);
  addOverviewKeys(keys);
  return keys;
}

const std::map<std::string, ColourKey>& allKeys() {
  static const std::map<std::string, ColourKey> keys = makeKeys();
  return keys;
}

}  // namespace

const ColourKey* commonViewColourKey(const std::string& viewName) {
  const auto& keys = allKeys();
  auto it = keys.find(viewName);
  return it == keys.end() ? nullptr : &it->second;
}

std::vector<std::string> commonViewsWithColourKeys() {
  std::vector<std::string> names;
  for (const auto& [name, key] : allKeys()) names.push_back(name);
  return names;
}

}  // namespace sl
