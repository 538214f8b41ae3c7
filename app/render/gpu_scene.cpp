#include "render/gpu_scene.h"

#include "gl/gl_util.h"
#include "scene/scene_effects.h"

#include <algorithm>
#include <cmath>

namespace sl {

GpuScene::GpuScene(const Scene& s) : scene(s) {
  for (const Mesh& m : s.meshes) {
    GpuMesh g;
    std::vector<float> interleaved;
    interleaved.reserve(m.positions.size() * 8);
    for (size_t i = 0; i < m.positions.size(); ++i) {
      const glm::vec3& p = m.positions[i];
      glm::vec3 n = i < m.normals.size() ? m.normals[i] : glm::vec3(0, 1, 0);
      glm::vec2 uv = i < m.uvs.size() ? m.uvs[i] : glm::vec2(0);
      interleaved.insert(interleaved.end(), {p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y});
    }
    glCreateBuffers(1, &g.vbo);
    glNamedBufferStorage(g.vbo, static_cast<GLsizeiptr>(interleaved.size() * sizeof(float)), interleaved.data(), 0);
    glCreateBuffers(1, &g.ibo);
    glNamedBufferStorage(g.ibo, static_cast<GLsizeiptr>(m.indices.size() * sizeof(uint32_t)), m.indices.data(), 0);
    glCreateVertexArrays(1, &g.vao);
    glVertexArrayVertexBuffer(g.vao, 0, g.vbo, 0, 8 * sizeof(float));
    glVertexArrayElementBuffer(g.vao, g.ibo);
    const GLuint offsets[3] = {0, 3, 6}, sizes[3] = {3, 3, 2};
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexArrayAttrib(g.vao, a);
      glVertexArrayAttribFormat(g.vao, a, static_cast<GLint>(sizes[a]), GL_FLOAT, GL_FALSE, offsets[a] * sizeof(float));
      glVertexArrayAttribBinding(g.vao, a, 0);
    }
    g.indexCount = static_cast<GLsizei>(m.indices.size());
    if (!m.positions.empty()) g.boundsMin = g.boundsMax = m.positions.front();
    for (const glm::vec3& p : m.positions)
      g.boundsMin = glm::min(g.boundsMin, p), g.boundsMax = glm::max(g.boundsMax, p);
    std::string name = "mesh " + m.name;
    label(GL_VERTEX_ARRAY, g.vao, name);
    label(GL_BUFFER, g.vbo, name + " vertices");
    label(GL_BUFFER, g.ibo, name + " indices");
    meshes.push_back(g);
  }
  for (const Texture& t : s.textures) {
    GLuint tex = 0;
    glCreateTextures(GL_TEXTURE_2D, 1, &tex);
    int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(std::max(t.width, t.height), 1))));
    glTextureStorage2D(tex, levels, GL_SRGB8_ALPHA8, t.width, t.height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(tex, 0, 0, 0, t.width, t.height, GL_RGBA, GL_UNSIGNED_BYTE, t.rgba.data());
    glGenerateTextureMipmap(tex);
    glTextureParameteri(tex, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTextureParameteri(tex, GL_TEXTURE_WRAP_T, GL_REPEAT);
    label(GL_TEXTURE, tex, "texture " + t.name);
    textures.push_back(tex);
  }
}

GpuScene::~GpuScene() {
  for (auto& g : meshes) {
    glDeleteVertexArrays(1, &g.vao);
    glDeleteBuffers(1, &g.vbo);
    glDeleteBuffers(1, &g.ibo);
  }
  if (!textures.empty()) glDeleteTextures(static_cast<GLsizei>(textures.size()), textures.data());
}

int materialVariant(const Material& m) { return (m.baseColorTexture >= 0 ? 1 : 0) | (m.alphaMask ? 2 : 0); }

std::string materialDefines(int variant) {
  std::string d;
  if (variant & 1) d += "#define SL_TEXTURED\n";
  if (variant & 2) d += "#define SL_ALPHA_MASK\n";
  return d;
}

bool PassPrograms::patches() const {
  for (const auto& stage : base_.stages)
    if (stage.first == GL_TESS_EVALUATION_SHADER) return true;
  return false;
}

const Program* PassPrograms::get(int variant) {
  if (!tried_[variant]) {
    tried_[variant] = true;
    ProgramSpec spec = base_;
    spec.prelude = materialDefines(variant) + spec.prelude;
    Program& p = shaders_.get(spec);
    if (p.valid()) {
      p.use();
      setup_(p, units_);
      programs_[variant] = &p;
    }
  }
  if (programs_[variant]) programs_[variant]->use();
  return programs_[variant];
}

namespace {

// True when the box (object space, placed by `model`) lies wholly outside one side of the clip
// window of `viewProj` in x or y, every corner in front of the projection (w > 0).
bool outsideWindow(const glm::mat4& viewProj, const glm::mat4& model, glm::vec3 lo, glm::vec3 hi) {
  const glm::mat4 m = viewProj * model;
  int left = 0, right = 0, below = 0, above = 0;
  for (int k = 0; k < 8; ++k) {
    const glm::vec3 corner((k & 1) ? hi.x : lo.x, (k & 2) ? hi.y : lo.y, (k & 4) ? hi.z : lo.z);
    const glm::vec4 c = m * glm::vec4(corner, 1.0f);
    if (!(c.w > 1e-6f)) return false;  // behind a projection's centre, or NaN: keep it
    left += c.x<-c.w, right += c.x> c.w, below += c.y<-c.w, above += c.y> c.w;
  }
  return left == 8 || right == 8 || below == 8 || above == 8;
}

}  // namespace

void GpuScene::draw(PassPrograms& programs, double time, double prevTime, GLenum cullFace, Only only,
                    const glm::mat4* cullTo) const {
  const GLenum mode = programs.patches() ? GL_PATCHES : GL_TRIANGLES;
  if (mode == GL_PATCHES) glPatchParameteri(GL_PATCH_VERTICES, 3);
  for (int variant = 0; variant < 4; ++variant) {
    const Program* program = nullptr;
    bool asked = false;
    for (size_t index = 0; index < scene.instances.size(); ++index) {
      const Instance& inst = scene.instances[index];
      const Mesh& m = scene.meshes[static_cast<size_t>(inst.mesh)];
      const Material& mat = scene.materials[static_cast<size_t>(m.material)];
      if (materialVariant(mat) != variant) continue;
      if (only != Only::All && (only == Only::SemiTransparent) != instanceSemiTransparent(scene, index)) continue;
      const GpuMesh& g = meshes[static_cast<size_t>(inst.mesh)];
      const glm::mat4 model = inst.transformAt(time);
      if (cullTo && outsideWindow(*cullTo, model, g.boundsMin, g.boundsMax)) continue;
      if (!asked) {
        program = programs.get(variant);
        asked = true;
      }
      if (!program) break;                                    // its error is reported by the shader library
      program->set("u_instanceId", static_cast<int>(index));  // G-buffer surface ids
      program->set("u_model", model);
      program->set("u_prevModel", inst.transformAt(prevTime));
      program->set("u_baseColor", mat.baseColor);
      program->set("u_alphaCutoff", mat.alphaCutoff);
      if (mat.baseColorTexture >= 0)
        programs.units().bind(*program, "u_baseColorTexture", textures[static_cast<size_t>(mat.baseColorTexture)]);
      if (cullFace && !mat.doubleSided) {
        glEnable(GL_CULL_FACE);
        glCullFace(cullFace);
      } else {
        glDisable(GL_CULL_FACE);
      }
      glBindVertexArray(g.vao);
      glDrawElements(mode, g.indexCount, GL_UNSIGNED_INT, nullptr);
    }
  }
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
}

}  // namespace sl
