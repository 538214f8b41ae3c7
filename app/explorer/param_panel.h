// The parameter panel, generated from a ParamSet's declarations: no key or range is written in
// UI code, so a parameter added to a technique part appears here without touching the explorer.
#pragma once

#include "core/params.h"

#include <string>

namespace sl {

// One widget per declaration (Float: slider, logarithmic when the declaration says so; Int:
// slider; Bool: checkbox; Enum: combo), with help, unit and range as tooltip. Every change goes
// through ParamSet::set; a rejected value leaves the set unchanged and its message in `error`.
// Returns true when a value changed.
bool drawParamPanel(ParamSet& params, std::string& error);

}  // namespace sl
