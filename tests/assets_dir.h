// The repository's assets folder, for tests that load scenes and meshes by path.
#pragma once

#include <string>

namespace sl::test {

inline const std::string kAssets = std::string(SHADOWLAB_SOURCE_DIR) + "/assets";

}  // namespace sl::test
