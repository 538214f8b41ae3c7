// What a technique family declares about itself, in one place: the family.cpp of its folder under
// techniques/ returns one Family (its parts and its presets). techniques/registry.cpp is the list
// of families, in the order `shadowlab list` shows them; nothing else names a family.
#pragma once

#include "part/part.h"

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
};

}  // namespace sl
