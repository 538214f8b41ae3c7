// The scene's meshes and textures on the GPU, and the one way every pass draws them.
#pragma once

#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "scene/scene.h"
#include "part/part.h"

#include <epoxy/gl.h>

#include <array>
#include <functional>
#include <vector>

namespace sl {

struct GpuMesh {
  GLuint vao = 0, vbo = 0, ibo = 0;
  GLsizei indexCount = 0;
  glm::vec3 boundsMin{0.0f}, boundsMax{0.0f};  // object space, for culling instances against a light view
};

// Materials come in four shader variants (bit 0: base-colour texture, bit 1: alpha mask), so
// that opaque untextured surfaces run no texture fetch and no discard: a software rasterizer
// executes both sides of every branch, and a discard anywhere disables early depth tests.
int materialVariant(const Material& m);
std::string materialDefines(int variant);

// The programs one pass draws the scene with: `base` plus each variant's defines, built on
// first use, then `setup` (the pass's uniforms and textures) runs once per program per pass.
// The pass's texture units are shared by its programs, the materials' textures included.
class PassPrograms {
 public:
  PassPrograms(ShaderLibrary& shaders, ProgramSpec base, ProgramSetup setup)
      : shaders_(shaders), base_(std::move(base)), setup_(std::move(setup)) {}
  const Program* get(int variant);  // bound with glUseProgram; nullptr when it does not build
  bool patches() const;             // tessellation stages: the scene is drawn as 3-vertex patches
  TextureUnits& units() { return units_; }

 private:
  ShaderLibrary& shaders_;
  ProgramSpec base_;
  ProgramSetup setup_;
  TextureUnits units_;
  std::array<const Program*, 4> programs_{};
  std::array<bool, 4> tried_{};
};

struct GpuScene {
  explicit GpuScene(const Scene& scene);
  ~GpuScene();
  GpuScene(const GpuScene&) = delete;
  GpuScene& operator=(const GpuScene&) = delete;

  // Draws every instance at `time`; sets u_model, u_prevModel (at prevTime) and material uniforms.
  // cullFace (GL_BACK/GL_FRONT, 0 = none) applies to single-sided materials only: double-sided
  // leaf cards must cast from both sides.
  // `only` keeps all instances, the opaque ones or the semi-transparent ones (scene_effects.h).
  enum class Only { All, Opaque, SemiTransparent };
  // cullTo: a light view's viewProj; instances whose bounds lie wholly beyond one side of its
  // window (|x| or |y| > w at every corner, all in front) are skipped: an orthographic or
  // projective light casts along its rays, so they cannot shadow anything in that view. Depth is
  // never culled (casters toward the light must stay).
  void draw(PassPrograms& programs, double time, double prevTime, GLenum cullFace = 0, Only only = Only::All,
            const glm::mat4* cullTo = nullptr) const;
  // The same draw of a tessellated pass (`patches`) with each drawn instance's triangles first
  // sorted by `sort` (passes/warp_classify.comp, bound with the pass's uniforms): those it puts
  // in the plain list are drawn by `plain`, the same pass without tessellation stages, the rest
  // as patches, both from indirect commands the sorting wrote (nothing read back).
  void drawSorted(PassPrograms& patches, PassPrograms& plain, const Program& sort, double time, GLenum cullFace,
                  Only only, const glm::mat4* cullTo) const;
  // The triangles the last drawSorted drew plain (x) and as patches (y), read back.
  glm::ivec2 sortedTriangles() const;

  const Scene& scene;
  std::vector<GpuMesh> meshes;
  std::vector<GLuint> textures;

 private:
  // The instances drawn, in the order draw() uses (material variant, then instance).
  struct Drawn {
    size_t index;
    int variant;
    glm::mat4 model;
  };
  std::vector<Drawn> drawnInstances(double time, Only only, const glm::mat4* cullTo) const;
  void setInstance(PassPrograms& programs, const Program& program, const Drawn& d, double prevTime,
                   GLenum cullFace) const;
  // drawSorted's lists (two slots of each instance's index count) and commands (two per
  // instance), made on first use.
  mutable GLuint sortedIndices_ = 0, sortedCommands_ = 0;
  // Each frame's commands before the sort counts: per instance its plain list's
  // DrawElementsIndirectCommand, then its patch list's (count 0, one instance, the list's first
  // slot in sortedIndices_, base vertex and instance 0).
  std::vector<GLuint> sortedCommandsAtStart_;
  GLuint sortedSlots_ = 0;
};

}  // namespace sl
