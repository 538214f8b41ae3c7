// The parameter panel, generated from a ParamSet's declarations: no key or range is written in
// UI code, so a parameter added to a technique part appears here without touching the explorer.
#pragma once

#include "core/params.h"

#include <set>
#include <string>
#include <vector>

namespace sl {

struct Scene;

// Linking across viewports: a small chain toggle before each widget (when given), and the keys
// this call changed (the caller copies those that are linked to the other viewports).
struct ParamLinks {
  std::set<std::string>* linked = nullptr;  // keys linked one by one; the toggle edits it
  bool all = false;                         // "link all": every toggle shows as on
  std::vector<std::string> changed;         // out: keys edited this frame
};

// One widget per declaration (Float: slider, logarithmic when the declaration says so; Int:
// slider; Bool: checkbox; Enum: combo), with help, unit and range as tooltip. Every change goes
// through ParamSet::set; a rejected value leaves the set unchanged and its message in `error`.
// Returns true when a value changed.
// Keys in `hidden` get no widget (their values stay as they are).
bool drawParamPanel(ParamSet& params, std::string& error, ParamLinks* links = nullptr,
                    const std::set<std::string>& hidden = {});

// The keys of `params` that mean nothing in `scene`: the "lights." ones (lights.shadowed, the
// texel budget) in a scene of one light.
std::set<std::string> paramsWithoutEffect(const ParamSet& params, const Scene* scene);

}  // namespace sl
