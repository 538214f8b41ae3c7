// The scene's meshes and textures on the GPU, and the one way every pass draws them.
#pragma once

#include "gl/shader_library.h"
#include "scene/scene.h"

#include <epoxy/gl.h>

#include <vector>

namespace sl {

struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0;
  GLsizei indexCount = 0;
};

struct GpuScene {
  explicit GpuScene(const Scene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  // Draws every instance at `time`; sets u_model, u_prevModel (at prevTime) and material uniforms.
  // cullFace (GL_BACK/GL_FRONT, 0 = none) applies to single-sided materials only: double-sided
  // leaf cards must cast from both sides.
  void draw(const Program& program, double time, double prevTime, GLenum cullFace = 0) const;

  const Scene& scene;
  std::vector<GpuMesh> meshes;
  std::vector<GLuint> textures;
};

}  // namespace sl
