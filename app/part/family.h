// What a technique family declares about itself, in one place: the family.cpp of its folder under
// techniques/ returns one Family (its parts, its presets, and the colour keys of its parts' views).
// techniques/registry.cpp is the list of families, in the order `shadowlab list` shows them; nothing else names a
// family.
#pragma once

#include "part/colour_key.h"
#include "part/part.h"

#include <map>

#include <memory>
#include <string>
#include <vector>

namespace sl {

struct Family {
  std::string id;       // its folder under techniques/ (the README there is its doc)
  std::string summary;  // one line: the idea and the papers
  std::vector<std::unique_ptr<Layout>> layouts;
  std::vector<std::unique_ptr<Representation>> representations;
  std::vector<std::unique_ptr<Accumulation>> accumulations;
  std::vector<Preset> presets;
  // What the colours of each debug view its parts' states offer (PartState::views) mean; a GL
  // test holds every offered view to a key here or among the common views.
  std::map<std::string, ColourKey> viewKeys;
};

}  // namespace sl
