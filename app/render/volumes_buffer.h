// The scene's participating media as the SSBO that shaders/common/volume_density.glsl reads
// (binding 6). The Renderer owns one, bound for its volumes pass and for the parts through
// PartContext::bindVolumes (the deep map's compress pass). Re-uploaded only when the volumes
// change.
#pragma once

#include "scene/scene.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <vector>

namespace sl {

// std430 data of Scene::volumes: a header vec4 (x = count), then three vec4 per volume.
std::vector<glm::vec4> packVolumes(const Scene& scene);

class VolumesBuffer {
 public:
  VolumesBuffer() = default;
  VolumesBuffer(const VolumesBuffer&) = delete;
  VolumesBuffer& operator=(const VolumesBuffer&) = delete;
  ~VolumesBuffer();
  void upload(const Scene& scene);
  void bind() const;  // to storage block SlVolumes (common/volume_density.glsl)

 private:
  GLuint id_ = 0;
  std::vector<glm::vec4> data_;
};

}  // namespace sl
