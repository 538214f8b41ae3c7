#include "part/part.h"

namespace sl {

LightSpace LayoutState::compute(const LayoutInput& in) { return layout_.compute(in); }

std::string Technique::label() const {
  std::string s = presetId + " (" + layout->id() + " + " + representation->id();
  if (accumulation->id() != "none") s += " + " + accumulation->id();
  return s + ")";
}

}  // namespace sl
