// The caster triangles of the irregular z-buffer: world space at the frame's time, as the
// reference tracer transforms them (inst.transformAt(time) in float), so both test the same
// triangles.
#include "irregular/izb_state.h"

#include <cstring>
#include <functional>

namespace sl {

namespace {

struct GpuTriangle {  // std430, 80 bytes: matches Triangle in shaders/passes/izb_common.glsl
  glm::vec4 a, b, c;  // xyz; w: instance + 1, triangle index in its mesh, material (as bits)
  glm::vec4 uv01;
  glm::vec4 uv2;
};

struct GpuMaterial {  // std430, 32 bytes: matches Material in izb_common.glsl
  uint32_t alphaOffset, width, height, masked;
  float cutoff, baseAlpha, pad0, pad1;
};

float bitsOf(uint32_t u) {
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}

void upload(GLuint& buffer, const void* data, size_t bytes, const char* name) {
  if (!buffer) {
    glCreateBuffers(1, &buffer);
  }
  // Never empty: a zero-sized SSBO cannot be bound.
  glNamedBufferData(buffer, static_cast<GLsizeiptr>(std::max<size_t>(bytes, 16)), nullptr, GL_STATIC_DRAW);
  if (bytes) glNamedBufferSubData(buffer, 0, static_cast<GLsizeiptr>(bytes), data);
  label(GL_BUFFER, buffer, name);
}

size_t sceneSignature(const Scene& s) {
  size_t h = std::hash<std::string>{}(s.sourcePath + "|" + s.name);
  h ^= s.instances.size() * 0x9e3779b97f4a7c15ull + s.meshes.size() * 31 + s.triangleCount();
  return h;
}

}  // namespace

IzbSceneBuffers::~IzbSceneBuffers() {
  for (GLuint b : {triangles, instanceBase, materials, alpha})
    if (b) glDeleteBuffers(1, &b);
}

void IzbSceneBuffers::update(const Scene& scene, double time) {
  const size_t signature = sceneSignature(scene);
  // A static scene keeps its triangles whatever the time; a moving one rebuilds per time.
  const bool sameTime = time_ == time || !scene.hasMotion();
  if (scene_ == &scene && signature_ == signature && sameTime && triangles) return;
  scene_ = &scene;
  signature_ = signature;
  time_ = time;

  // Alpha of every masked material's texture, 4 texels per uint (one byte each).
  std::vector<GpuMaterial> mats(std::max<size_t>(scene.materials.size(), 1), GpuMaterial{0, 0, 0, 0, 0.5f, 1.0f, 0, 0});
  std::vector<uint8_t> alphaBytes;
  anyMasked = false;
  for (size_t m = 0; m < scene.materials.size(); ++m) {
    const Material& mat = scene.materials[m];
    mats[m].masked = mat.alphaMask ? 1u : 0u;
    anyMasked = anyMasked || mat.alphaMask;
    mats[m].cutoff = mat.alphaCutoff;
    mats[m].baseAlpha = mat.baseColor.a;
    if (!mat.alphaMask || mat.baseColorTexture < 0 ||
        static_cast<size_t>(mat.baseColorTexture) >= scene.textures.size())
      continue;
    const Texture& t = scene.textures[static_cast<size_t>(mat.baseColorTexture)];
    if (t.width <= 0 || t.height <= 0 || t.rgba.size() < static_cast<size_t>(t.width) * t.height * 4) continue;
    mats[m].alphaOffset = static_cast<uint32_t>(alphaBytes.size());
    mats[m].width = static_cast<uint32_t>(t.width);
    mats[m].height = static_cast<uint32_t>(t.height);
    for (size_t i = 0; i < static_cast<size_t>(t.width) * t.height; ++i) alphaBytes.push_back(t.rgba[4 * i + 3]);
  }
  alphaBytes.resize((alphaBytes.size() + 3) / 4 * 4, 0);

  std::vector<GpuTriangle> tris;
  std::vector<uint32_t> base(std::max<size_t>(scene.instances.size(), 1), 0);
  tris.reserve(scene.triangleCount());
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    base[i] = static_cast<uint32_t>(tris.size());
    const Instance& inst = scene.instances[i];
    if (inst.mesh < 0 || static_cast<size_t>(inst.mesh) >= scene.meshes.size()) continue;
    const Mesh& mesh = scene.meshes[static_cast<size_t>(inst.mesh)];
    const glm::mat4 model = inst.transformAt(time);
    const uint32_t material =
        mesh.material >= 0 && static_cast<size_t>(mesh.material) < scene.materials.size() ? mesh.material : 0;
    auto world = [&](uint32_t v) { return glm::vec3(model * glm::vec4(mesh.positions[v], 1.0f)); };
    auto uv = [&](uint32_t v) { return v < mesh.uvs.size() ? mesh.uvs[v] : glm::vec2(0.0f); };
    for (size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
      const uint32_t i0 = mesh.indices[t], i1 = mesh.indices[t + 1], i2 = mesh.indices[t + 2];
      const uint32_t n = static_cast<uint32_t>(mesh.positions.size());
      GpuTriangle g{};
      // An index out of range (the loader rejects them) would read garbage: a degenerate
      // triangle at the origin stands in, which no ray hits.
      if (i0 < n && i1 < n && i2 < n) {
        g.a = glm::vec4(world(i0), 0.0f);
        g.b = glm::vec4(world(i1), 0.0f);
        g.c = glm::vec4(world(i2), 0.0f);
        g.uv01 = glm::vec4(uv(i0), uv(i1));
        g.uv2 = glm::vec4(uv(i2), 0.0f, 0.0f);
      }
      g.a.w = bitsOf(static_cast<uint32_t>(i + 1));
      g.b.w = bitsOf(static_cast<uint32_t>(t / 3));
      g.c.w = bitsOf(material);
      tris.push_back(g);
    }
  }
  triangleCount = static_cast<uint32_t>(tris.size());
  upload(triangles, tris.data(), tris.size() * sizeof(GpuTriangle), "izb triangles");
  upload(instanceBase, base.data(), base.size() * sizeof(uint32_t), "izb instance base");
  upload(materials, mats.data(), mats.size() * sizeof(GpuMaterial), "izb materials");
  upload(alpha, alphaBytes.data(), alphaBytes.size(), "izb alpha masks");
  bytes = static_cast<long long>(tris.size() * sizeof(GpuTriangle) + base.size() * 4 +
                                 mats.size() * sizeof(GpuMaterial) + alphaBytes.size());
}

}  // namespace sl
