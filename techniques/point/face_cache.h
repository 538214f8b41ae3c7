// Faces kept from an earlier frame (beyond the papers: the virtual map's page cache applied to a
// point light's faces). A face's layer is drawn again only when what it would hold changed: its
// view (the light moved, or the camera's fit of that face), the technique's values or shaders,
// the scene, or an instance that moves inside the face's frustum, where it is now or where it was
// when the layer was drawn. A still camera over a static scene redraws nothing; an object moving
// under one face redraws that face alone. No GL here: the state asks it which faces to keep.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace sl {

// What a face's layer holds.
struct FaceContent {
  glm::mat4 viewProj{0.0f};
  uint64_t sceneGeneration = 0;
  uint64_t techniqueStamp = 0;  // the parameter values and the shader library's builds
  int size = 0;
  // false: a view that is no projective map (a paraboloid's hemisphere), where any moving
  // instance redraws it (its frustum planes would not bound it).
  bool projective = true;
  glm::vec4 paraboloidWindow{0.0f, 0.0f, 1.0f,
                             1.0f};  // a paraboloid's fitted window (its viewProj does not move with it)
  bool operator==(const FaceContent&) const = default;
};

class FaceCache {
 public:
  // Which needed faces may keep their layer this frame, drawn at scene time `time`.
  std::vector<bool> keep(const std::vector<FaceContent>& now, const std::vector<bool>& needed, const Scene& scene,
                         double time) const;
  // After the plan: `drawn` faces now hold now[f] drawn at `time`; the others keep what they
  // held when the representation keeps its layers, and hold nothing otherwise.
  void record(const std::vector<FaceContent>& now, const std::vector<bool>& drawn, bool layersKept, double time);
  void clear() { held_.clear(); }

 private:
  struct Held {
    FaceContent content;
    double time = 0;
    bool valid = false;
  };
  std::vector<Held> held_;
};

// True when some instance that moves (Instance::motion) lies, at scene time `a` or `b`, at least
// partly inside the clip volume of `viewProj` (its bounds against the volume's planes).
bool movingInstanceInView(const Scene& scene, const glm::mat4& viewProj, double a, double b);

}  // namespace sl
