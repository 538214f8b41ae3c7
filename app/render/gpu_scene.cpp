#include "render/gpu_scene.h"

#include "gl/gl_util.h"
#include "gl/storage_blocks.h"
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
  // drawSorted's lists: each instance's two, each as long as its indices.
  for (const Instance& inst : s.instances) {
    const GLuint count = static_cast<GLuint>(meshes[static_cast<size_t>(inst.mesh)].indexCount);
    sortedCommandsAtStart_.insert(sortedCommandsAtStart_.end(),
                                  {0, 1, sortedSlots_, 0, 0, 0, 1, sortedSlots_ + count, 0, 0});
    sortedSlots_ += 2 * count;
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
  if (sortedIndices_) glDeleteBuffers(1, &sortedIndices_);
  if (sortedCommands_) glDeleteBuffers(1, &sortedCommands_);
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

constexpr size_t kCommandUints = 5;  // a DrawElementsIndirectCommand (drawSorted)

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

std::vector<GpuScene::Drawn> GpuScene::drawnInstances(double time, Only only, const glm::mat4* cullTo) const {
  std::vector<Drawn> drawn;
  for (int variant = 0; variant < 4; ++variant)
    for (size_t index = 0; index < scene.instances.size(); ++index) {
      const Instance& inst = scene.instances[index];
      const Mesh& m = scene.meshes[static_cast<size_t>(inst.mesh)];
      if (materialVariant(scene.materials[static_cast<size_t>(m.material)]) != variant) continue;
      if (only != Only::All && (only == Only::SemiTransparent) != instanceSemiTransparent(scene, index)) continue;
      const GpuMesh& g = meshes[static_cast<size_t>(inst.mesh)];
      const glm::mat4 model = inst.transformAt(time);
      if (cullTo && outsideWindow(*cullTo, model, g.boundsMin, g.boundsMax)) continue;
      drawn.push_back({index, variant, model});
    }
  return drawn;
}

void GpuScene::setInstance(PassPrograms& programs, const Program& program, const Drawn& d, double prevTime,
                           GLenum cullFace) const {
  const Instance& inst = scene.instances[d.index];
  const Material& mat = scene.materials[static_cast<size_t>(scene.meshes[static_cast<size_t>(inst.mesh)].material)];
  program.set("u_instanceId", static_cast<int>(d.index));  // G-buffer surface ids
  program.set("u_model", d.model);
  program.set("u_prevModel", inst.transformAt(prevTime));
  program.set("u_baseColor", mat.baseColor);
  program.set("u_alphaCutoff", mat.alphaCutoff);
  if (mat.baseColorTexture >= 0)
    programs.units().bind(program, "u_baseColorTexture", textures[static_cast<size_t>(mat.baseColorTexture)]);
  if (cullFace && !mat.doubleSided) {
    glEnable(GL_CULL_FACE);
    glCullFace(cullFace);
  } else {
    glDisable(GL_CULL_FACE);
  }
}

void GpuScene::draw(PassPrograms& programs, double time, double prevTime, GLenum cullFace, Only only,
                    const glm::mat4* cullTo) const {
  const GLenum mode = programs.patches() ? GL_PATCHES : GL_TRIANGLES;
  if (mode == GL_PATCHES) glPatchParameteri(GL_PATCH_VERTICES, 3);
  const Program* program = nullptr;
  int variant = -1;
  for (const Drawn& d : drawnInstances(time, only, cullTo)) {
    if (d.variant != variant) program = programs.get(variant = d.variant);
    if (!program) continue;  // its error is reported by the shader library
    setInstance(programs, *program, d, prevTime, cullFace);
    const GpuMesh& g = meshes[static_cast<size_t>(scene.instances[d.index].mesh)];
    glBindVertexArray(g.vao);
    glDrawElements(mode, g.indexCount, GL_UNSIGNED_INT, nullptr);
  }
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
}

// Each drawn instance's triangles are sorted into its two lists by one dispatch, then every
// instance draws its plain list with `plain` and its patch list with `patches` from the commands
// the dispatches counted; the lists replace the mesh's indices for those draws.
void GpuScene::drawSorted(PassPrograms& patches, PassPrograms& plain, const Program& sort, double time, GLenum cullFace,
                          Only only, const glm::mat4* cullTo) const {
  const std::vector<Drawn> drawn = drawnInstances(time, only, cullTo);
  if (!sortedIndices_) {
    glCreateBuffers(1, &sortedIndices_);
    glNamedBufferStorage(sortedIndices_, static_cast<GLsizeiptr>(std::max(sortedSlots_, 1u) * sizeof(GLuint)), nullptr,
                         0);
    glCreateBuffers(1, &sortedCommands_);
    glNamedBufferStorage(sortedCommands_,
                         static_cast<GLsizeiptr>(std::max<size_t>(sortedCommandsAtStart_.size(), 1) * sizeof(GLuint)),
                         nullptr, GL_DYNAMIC_STORAGE_BIT);
    label(GL_BUFFER, sortedIndices_, "casters sorted for tessellation: indices");
    label(GL_BUFFER, sortedCommands_, "casters sorted for tessellation: commands");
  }
  const std::vector<GLuint>& commands = sortedCommandsAtStart_;
  if (!commands.empty())
    glNamedBufferSubData(sortedCommands_, 0, static_cast<GLsizeiptr>(commands.size() * sizeof(GLuint)),
                         commands.data());
  sort.use();
  bindStorage("SplitIndices", sortedIndices_);
  bindStorage("SplitCommands", sortedCommands_);
  for (const Drawn& d : drawn) {
    const GpuMesh& g = meshes[static_cast<size_t>(scene.instances[d.index].mesh)];
    bindStorage("CasterVertices", g.vbo);
    bindStorage("CasterIndices", g.ibo);
    sort.set("u_model", d.model);
    sort.set("u_triangles", static_cast<int>(g.indexCount / 3));
    const size_t command = d.index * 2 * kCommandUints;
    sort.set("u_command", static_cast<int>(command));
    sort.set("u_plainFirst", static_cast<int>(commands[command + 2]));
    sort.set("u_patchFirst", static_cast<int>(commands[command + kCommandUints + 2]));
    glDispatchCompute(static_cast<GLuint>((g.indexCount / 3 + 63) / 64), 1, 1);
  }
  glMemoryBarrier(GL_COMMAND_BARRIER_BIT | GL_ELEMENT_ARRAY_BARRIER_BIT);
  glPatchParameteri(GL_PATCH_VERTICES, 3);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, sortedCommands_);
  for (const Drawn& d : drawn) {
    const GpuMesh& g = meshes[static_cast<size_t>(scene.instances[d.index].mesh)];
    glBindVertexArray(g.vao);
    glVertexArrayElementBuffer(g.vao, sortedIndices_);
    for (int list = 0; list < 2; ++list) {
      PassPrograms& programs = list == 0 ? plain : patches;
      const Program* program = programs.get(d.variant);
      if (!program) continue;  // its error is reported by the shader library
      setInstance(programs, *program, d, time, cullFace);
      const GLintptr offset =
          static_cast<GLintptr>((d.index * 2 + static_cast<size_t>(list)) * kCommandUints * sizeof(GLuint));
      glDrawElementsIndirect(list == 0 ? GL_TRIANGLES : GL_PATCHES, GL_UNSIGNED_INT,
                             reinterpret_cast<const void*>(offset));
    }
    glVertexArrayElementBuffer(g.vao, g.ibo);
  }
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  glDisable(GL_CULL_FACE);
}

glm::ivec2 GpuScene::sortedTriangles() const {
  if (!sortedCommands_) return glm::ivec2(0);
  std::vector<GLuint> commands(sortedCommandsAtStart_.size());
  glGetNamedBufferSubData(sortedCommands_, 0, static_cast<GLsizeiptr>(commands.size() * sizeof(GLuint)),
                          commands.data());
  glm::ivec2 triangles(0);
  for (size_t c = 0; c < commands.size(); c += kCommandUints)
    triangles[(c / kCommandUints) % 2] += static_cast<int>(commands[c] / 3);
  return triangles;
}

}  // namespace sl
