// The parameter panel, generated from a ParamSet's declarations: no key or range is written in
// UI code, so a parameter added to a technique part appears here without touching the explorer.
#pragma once

#include "core/params.h"

#include <set>
#include <string>
#include <vector>

namespace sl {

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
bool drawParamPanel(ParamSet& params, std::string& error, ParamLinks* links = nullptr);

}  // namespace sl
