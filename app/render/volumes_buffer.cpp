#include "render/volumes_buffer.h"
#include "gl/storage_blocks.h"

#include "gl/gl_util.h"

namespace sl {

std::vector<glm::vec4> packVolumes(const Scene& scene) {
  std::vector<glm::vec4> data(1 + 3 * scene.volumes.size(), glm::vec4(0.0f));
  data[0].x = float(scene.volumes.size());
  for (size_t i = 0; i < scene.volumes.size(); ++i) {
    const Volume& v = scene.volumes[i];
    data[1 + 3 * i] = glm::vec4(v.center, v.shape == Volume::Shape::Sphere ? 1.0f : 0.0f);
    data[2 + 3 * i] = glm::vec4(v.halfSize, v.extinction);
    // Octaves and seed as floats: exact below 2^24 (the scene loader bounds them).
    data[3 + 3 * i] = glm::vec4(v.noiseScale, v.noise, float(v.octaves), float(v.seed));
  }
  return data;
}

VolumesBuffer::~VolumesBuffer() {
  if (id_) glDeleteBuffers(1, &id_);
}

void VolumesBuffer::upload(const Scene& scene) {
  std::vector<glm::vec4> data = packVolumes(scene);
  if (id_ && data == data_) return;
  data_ = std::move(data);
  if (id_) glDeleteBuffers(1, &id_);
  glCreateBuffers(1, &id_);
  glNamedBufferStorage(id_, static_cast<GLsizeiptr>(data_.size() * sizeof(glm::vec4)), data_.data(), 0);
  label(GL_BUFFER, id_, "volumes");
}

void VolumesBuffer::bind() const { bindStorage("SlVolumes", id_); }

}  // namespace sl
