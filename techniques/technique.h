// The registry: every family's parts and presets (techniques/registry.cpp lists the families),
// and techniques built from a preset. Front ends include this; the renderer and the families
// include the part SDK (part/part.h) instead.
#pragma once

#include "part/family.h"
#include "part/part.h"

#include <memory>
#include <string>
#include <vector>

namespace sl {

// The registry of parts and presets (techniques/registry.cpp lists every family).
const std::vector<Family>& allFamilies();
const std::vector<const Layout*>& allLayouts();
const std::vector<const Representation*>& allRepresentations();
const std::vector<const Accumulation*>& allAccumulations();
const std::vector<Preset>& allPresets();
const Layout* findLayout(const std::string& id);
const Representation* findRepresentation(const std::string& id);
const Accumulation* findAccumulation(const std::string& id);
const Preset* findPreset(const std::string& id);
// What the colours of a debug view mean: a common view's key (part/common_view_keys.h) or the key its
// family declares (Family::viewKeys); nullptr for views whose colours are the scene itself.
const ColourKey* viewColourKey(const std::string& viewName);
// Every view with a key, common and of every family (for tests and `shadowlab list`).
std::vector<std::string> viewsWithColourKeys();
// Parameters every technique has (shadow-map size, bias, culling, snapping).
const std::vector<ParamDecl>& commonParams();

// The parameter that picks the composition's layout (every technique has it; commonParams).
inline constexpr const char* kLayoutParam = "technique.layout";

// Builds a technique from a preset id and applies "key=value" overrides; throws ParamError
// with a clear message for an unknown preset or a bad override. An override of
// technique.layout puts the preset's representation and accumulation over that layout (its
// parameters can be set in the same list).
Technique makeTechnique(const std::string& presetId, const std::vector<std::string>& overrides = {});
// After technique.layout was changed in place (a panel, a sweep): the technique rebuilt over that
// layout with every value the new one shares carried over; unchanged otherwise.
Technique recomposed(const Technique& t);

}  // namespace sl
