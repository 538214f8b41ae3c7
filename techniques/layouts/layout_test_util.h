// The light space a preset's layout computes for a scene camera, without a GPU (layout tests).
#pragma once

#include "technique.h"

#include <string>
#include <vector>

namespace sl::test {

inline LightSpace layoutFor(const std::string& preset, const Scene& scene, const Camera& cam,
                            std::vector<std::string> overrides = {}, float aspect = 16.0f / 9.0f) {
  Technique t = makeTechnique(preset, overrides);
  LayoutInput in;
  in.scene = &scene;
  in.cameraView = cameraView(cam);
  in.cameraProj = cameraProjection(cam, aspect);
  in.params = &t.params;
  return t.layout->compute(in);
}

}  // namespace sl::test
