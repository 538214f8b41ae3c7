// glTF 2.0 import through tinygltf. tinygltf parses the file and decodes images; everything it
// hands back (accessor ranges, indices, node links) is checked here before use, because a bad
// file must produce a SceneError, not a crash or a silent garbage mesh.
#include "scene/gltf_loader.h"

#include "scene/mesh_ops.h"

#include <tiny_gltf.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <tuple>
#include <utility>

namespace sl {
namespace {

class GltfImporter {
 public:
  GltfImporter(Scene& scene, std::string path) : scene_(scene), path_(std::move(path)) {}

  void run(const glm::mat4& modelTransform) {
    load();
    std::vector<int> roots;
    if (!model_.scenes.empty()) {
      int s = model_.defaultScene;
      if (s < 0) s = 0;
      if (size_t(s) >= model_.scenes.size()) fail("default scene " + std::to_string(s) + " does not exist");
      roots = model_.scenes[s].nodes;
    } else {
      // No scene list: every node that is nobody's child is a root.
      std::vector<bool> isChild(model_.nodes.size(), false);
      for (const auto& n : model_.nodes) {
        for (int c : n.children) {
          if (c >= 0 && size_t(c) < isChild.size()) isChild[c] = true;
        }
      }
      for (size_t i = 0; i < model_.nodes.size(); ++i) {
        if (!isChild[i]) roots.push_back(int(i));
      }
    }
    for (int r : roots) visitNode(r, modelTransform, 0);
    if (repairedNormals_ > 0) {
      std::fprintf(stderr,
                   "%s: %zu vertex normals were zero or not finite; replaced by their triangles' flat normals\n",
                   path_.c_str(), repairedNormals_);
    }
  }

 private:
  [[noreturn]] void fail(const std::string& what) const { throw SceneError(path_ + ": " + what); }

  void load() {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (!fs::is_regular_file(path_, ec)) fail("glTF file not found or not a regular file");
    tinygltf::TinyGLTF loader;
    std::string err, warn;
    const std::string ext = fs::path(path_).extension().string();
    const bool binary = ext == ".glb" || ext == ".GLB";
    const bool ok = binary ? loader.LoadBinaryFromFile(&model_, &err, &warn, path_)
                           : loader.LoadASCIIFromFile(&model_, &err, &warn, path_);
    warn_ = warn;
    if (!ok || !err.empty()) {
      fail("cannot load glTF: " + (err.empty() ? std::string("unknown error") : err) +
           (warn.empty() ? "" : " (warnings: " + warn + ")"));
    }
  }

  glm::mat4 localMatrix(const tinygltf::Node& n, const std::string& where) const {
    if (n.matrix.size() == 16) return glm::make_mat4(n.matrix.data());  // column-major, like glm
    if (!n.matrix.empty()) fail(where + ".matrix: expected 16 numbers");
    glm::mat4 m(1.0f);
    if (n.translation.size() == 3) {
      m = glm::translate(m, glm::vec3(n.translation[0], n.translation[1], n.translation[2]));
    }
    if (n.rotation.size() == 4) {
      // glTF stores quaternions as x,y,z,w; glm's constructor takes w first.
      const glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
      m = m * glm::mat4_cast(glm::normalize(q));
    }
    if (n.scale.size() == 3) m = glm::scale(m, glm::vec3(n.scale[0], n.scale[1], n.scale[2]));
    return m;
  }

  void visitNode(int index, const glm::mat4& parent, int depth) {
    const std::string where = "nodes[" + std::to_string(index) + "]";
    if (index < 0 || size_t(index) >= model_.nodes.size()) fail(where + ": node index out of range");
    // A valid hierarchy is a forest; a cycle would otherwise recurse forever.
    if (depth > 256) fail(where + ": node hierarchy deeper than 256 levels (cycle?)");
    const tinygltf::Node& node = model_.nodes[index];
    const glm::mat4 world = parent * localMatrix(node, where);
    if (node.mesh >= 0) addMeshInstances(node, world, where);
    for (int c : node.children) visitNode(c, world, depth + 1);
  }

  void addMeshInstances(const tinygltf::Node& node, const glm::mat4& world, const std::string& where) {
    if (size_t(node.mesh) >= model_.meshes.size()) {
      fail(where + ".mesh: mesh index " + std::to_string(node.mesh) + " out of range");
    }
    const tinygltf::Mesh& gm = model_.meshes[node.mesh];
    const bool mirrored = mirrors(world);
    for (size_t p = 0; p < gm.primitives.size(); ++p) {
      const int meshIndex = primitiveMesh(node.mesh, int(p), mirrored);
      if (meshIndex < 0) continue;  // not a triangle list
      Instance inst;
      inst.name = (node.name.empty() ? gm.name : node.name) + "/" + std::to_string(p);
      inst.mesh = meshIndex;
      inst.transform = world;
      scene_.instances.push_back(inst);
    }
  }

  // Scene mesh index for a glTF primitive, converted once even when many nodes share it.
  // glTF 2.0 (3.7.4): a node whose global transform has a negative determinant reverses the
  // winding, so its front faces stay front faces for culling and gl_FrontFacing. Such nodes
  // get their own copy with reversed triangles; nodes that do not mirror keep the original.
  int primitiveMesh(int mesh, int prim, bool mirrored) {
    const auto key = std::make_tuple(mesh, prim, mirrored);
    auto it = meshCache_.find(key);
    if (it != meshCache_.end()) return it->second;
    int result = -1;
    auto other = meshCache_.find(std::make_tuple(mesh, prim, !mirrored));
    if (other != meshCache_.end()) {
      if (other->second >= 0) {
        Mesh copy = scene_.meshes[size_t(other->second)];
        reverseWinding(copy);
        copy.name = model_.meshes[mesh].name + "/" + std::to_string(prim) + (mirrored ? " (mirrored)" : "");
        scene_.meshes.push_back(std::move(copy));
        result = int(scene_.meshes.size() - 1);
      }
    } else {
      result = convertPrimitive(mesh, prim);
      if (result >= 0 && mirrored) {
        reverseWinding(scene_.meshes[size_t(result)]);
        scene_.meshes[size_t(result)].name += " (mirrored)";
      }
    }
    meshCache_[key] = result;
    return result;
  }

  struct AccessorData {
    std::vector<float> values;  // count * components, normalized where the accessor says so
    size_t count = 0;
    int components = 0;
  };

  // Reads an accessor into floats (or exact integers for index types). `allowed` lists
  // accepted component types; normalized integer types are only accepted when `normalizedOk`.
  AccessorData readAccessor(int index, const std::string& where, int expectedType, std::initializer_list<int> allowed,
                            bool normalizedOk) const {
    const std::string aw = where + " (accessor " + std::to_string(index) + ")";
    if (index < 0 || size_t(index) >= model_.accessors.size()) fail(aw + ": accessor index out of range");
    const tinygltf::Accessor& acc = model_.accessors[index];
    if (acc.sparse.isSparse) fail(aw + ": sparse accessors are not supported");
    if (acc.type != expectedType) fail(aw + ": unexpected accessor type " + std::to_string(acc.type));
    bool typeOk = false;
    for (int t : allowed) {
      const bool isFloatOrIndex = t == TINYGLTF_COMPONENT_TYPE_FLOAT || !normalizedOk;
      if (t == acc.componentType && (isFloatOrIndex || acc.normalized)) typeOk = true;
    }
    if (!typeOk) {
      fail(aw + ": unsupported component type " + std::to_string(acc.componentType) +
           (acc.normalized ? " (normalized)" : ""));
    }
    AccessorData out;
    out.count = acc.count;
    out.components = tinygltf::GetNumComponentsInType(uint32_t(acc.type));
    const int compSize = tinygltf::GetComponentSizeInBytes(uint32_t(acc.componentType));
    if (out.components <= 0 || compSize <= 0) fail(aw + ": invalid type or component type");
    if (acc.bufferView < 0) {
      // glTF: no buffer view means all zeros. Cap the count so a bogus one can't exhaust memory.
      if (out.count > (size_t(1) << 26)) fail(aw + ": count too large for an accessor without data");
      out.values.assign(out.count * size_t(out.components), 0.0f);
      return out;
    }
    if (size_t(acc.bufferView) >= model_.bufferViews.size()) fail(aw + ": bufferView index out of range");
    const tinygltf::BufferView& bv = model_.bufferViews[acc.bufferView];
    if (bv.buffer < 0 || size_t(bv.buffer) >= model_.buffers.size()) fail(aw + ": buffer index out of range");
    const std::vector<unsigned char>& data = model_.buffers[bv.buffer].data;
    const size_t elemSize = size_t(compSize) * size_t(out.components);
    const size_t stride = bv.byteStride ? bv.byteStride : elemSize;
    if (stride < elemSize) fail(aw + ": byteStride smaller than the element size");
    if (bv.byteOffset > data.size() || bv.byteLength > data.size() - bv.byteOffset) {
      fail(aw + ": bufferView range exceeds buffer " + std::to_string(bv.buffer) + " (" + std::to_string(data.size()) +
           " bytes)");
    }
    if (out.count == 0) return out;
    // Checked in this order so that a huge count cannot overflow the byte arithmetic.
    if (acc.byteOffset > bv.byteLength || out.count - 1 > (bv.byteLength - acc.byteOffset) / stride ||
        acc.byteOffset + stride * (out.count - 1) + elemSize > bv.byteLength) {
      fail(aw + ": accessor range exceeds its bufferView (count " + std::to_string(out.count) + ")");
    }
    out.values.assign(out.count * size_t(out.components), 0.0f);
    const unsigned char* base = data.data() + bv.byteOffset + acc.byteOffset;
    for (size_t i = 0; i < out.count; ++i) {
      const unsigned char* e = base + i * stride;
      for (int c = 0; c < out.components; ++c) {
        out.values[i * size_t(out.components) + size_t(c)] =
            component(e + size_t(c) * size_t(compSize), acc.componentType, acc.normalized);
      }
    }
    return out;
  }

  static float component(const unsigned char* p, int type, bool normalized) {
    switch (type) {
      case TINYGLTF_COMPONENT_TYPE_FLOAT: {
        float v;
        std::memcpy(&v, p, 4);
        return v;
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
        return normalized ? float(*p) / 255.0f : float(*p);
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
        uint16_t v;
        std::memcpy(&v, p, 2);
        return normalized ? float(v) / 65535.0f : float(v);
      }
      case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
        // Only used for indices; callers read those through readIndices to stay exact.
        uint32_t v;
        std::memcpy(&v, p, 4);
        return float(v);
      }
      default:
        return 0.0f;
    }
  }

  // Indices are read separately so 32-bit values above 2^24 stay exact.
  std::vector<uint32_t> readIndices(int index, const std::string& where) const {
    const auto allowed = {TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
                          TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT};
    // Validates ranges and types; the float values are discarded for uint32 sources.
    AccessorData d = readAccessor(index, where, TINYGLTF_TYPE_SCALAR, allowed, false);
    std::vector<uint32_t> out(d.count);
    const tinygltf::Accessor& acc = model_.accessors[index];
    if (acc.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT || acc.bufferView < 0) {
      for (size_t i = 0; i < d.count; ++i) out[i] = uint32_t(d.values[i]);
      return out;
    }
    const tinygltf::BufferView& bv = model_.bufferViews[acc.bufferView];
    const size_t stride = bv.byteStride ? bv.byteStride : 4;
    const unsigned char* base = model_.buffers[bv.buffer].data.data() + bv.byteOffset + acc.byteOffset;
    for (size_t i = 0; i < d.count; ++i) std::memcpy(&out[i], base + i * stride, 4);
    return out;
  }

  int convertPrimitive(int meshIndex, int primIndex) {
    const tinygltf::Primitive& prim = model_.meshes[meshIndex].primitives[primIndex];
    const std::string where = "meshes[" + std::to_string(meshIndex) + "].primitives[" + std::to_string(primIndex) + "]";
    // Points, lines and strips/fans are skipped: shadow casters here are triangle lists.
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) return -1;
    auto attr = [&](const char* name) {
      auto it = prim.attributes.find(name);
      return it == prim.attributes.end() ? -1 : it->second;
    };
    const int posAcc = attr("POSITION");
    if (posAcc < 0) fail(where + ": no POSITION attribute");
    const AccessorData pos =
        readAccessor(posAcc, where + ".POSITION", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false);
    const size_t vertexCount = pos.count;
    Mesh mesh;
    mesh.name = model_.meshes[meshIndex].name + "/" + std::to_string(primIndex);
    mesh.positions.resize(vertexCount);
    for (size_t i = 0; i < vertexCount; ++i) {
      mesh.positions[i] = glm::vec3(pos.values[i * 3], pos.values[i * 3 + 1], pos.values[i * 3 + 2]);
      if (!std::isfinite(mesh.positions[i].x) || !std::isfinite(mesh.positions[i].y) ||
          !std::isfinite(mesh.positions[i].z)) {
        fail(where + ".POSITION: vertex " + std::to_string(i) + " is not finite");
      }
    }
    const int nrmAcc = attr("NORMAL");
    if (nrmAcc >= 0) {
      const AccessorData n =
          readAccessor(nrmAcc, where + ".NORMAL", TINYGLTF_TYPE_VEC3, {TINYGLTF_COMPONENT_TYPE_FLOAT}, false);
      if (n.count != vertexCount) fail(where + ".NORMAL: count differs from POSITION count");
      mesh.normals.resize(vertexCount);
      for (size_t i = 0; i < vertexCount; ++i) {
        mesh.normals[i] = glm::vec3(n.values[i * 3], n.values[i * 3 + 1], n.values[i * 3 + 2]);
      }
    }
    mesh.uvs.assign(vertexCount, glm::vec2(0.0f));
    const int uvAcc = attr("TEXCOORD_0");
    if (uvAcc >= 0) {
      const AccessorData t = readAccessor(uvAcc, where + ".TEXCOORD_0", TINYGLTF_TYPE_VEC2,
                                          {TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
                                           TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT},
                                          true);
      if (t.count != vertexCount) fail(where + ".TEXCOORD_0: count differs from POSITION count");
      for (size_t i = 0; i < vertexCount; ++i) mesh.uvs[i] = glm::vec2(t.values[i * 2], t.values[i * 2 + 1]);
    }
    if (prim.indices >= 0) {
      mesh.indices = readIndices(prim.indices, where + ".indices");
      for (size_t i = 0; i < mesh.indices.size(); ++i) {
        if (mesh.indices[i] >= vertexCount) {
          fail(where + ".indices: index " + std::to_string(mesh.indices[i]) + " at position " + std::to_string(i) +
               " out of range (vertex count " + std::to_string(vertexCount) + ")");
        }
      }
    } else {
      mesh.indices.resize(vertexCount);
      for (size_t i = 0; i < vertexCount; ++i) mesh.indices[i] = uint32_t(i);
    }
    mesh.indices.resize(mesh.indices.size() / 3 * 3);  // a trailing partial triangle is ignored
    if (mesh.normals.empty())
      makeFlatNormals(mesh);
    else
      repairedNormals_ += repairNormals(mesh);
    mesh.material = materialIndex(prim.material, where);
    scene_.meshes.push_back(std::move(mesh));
    return int(scene_.meshes.size() - 1);
  }

  int materialIndex(int gltfMaterial, const std::string& where) {
    if (gltfMaterial < 0) {
      if (defaultMaterial_ < 0) {
        scene_.materials.push_back(Material{});
        defaultMaterial_ = int(scene_.materials.size() - 1);
      }
      return defaultMaterial_;
    }
    if (size_t(gltfMaterial) >= model_.materials.size()) {
      fail(where + ".material: material index " + std::to_string(gltfMaterial) + " out of range");
    }
    auto it = materialCache_.find(gltfMaterial);
    if (it != materialCache_.end()) return it->second;
    const tinygltf::Material& gm = model_.materials[gltfMaterial];
    const std::string mw = "materials[" + std::to_string(gltfMaterial) + "]";
    Material m;
    const auto& f = gm.pbrMetallicRoughness.baseColorFactor;
    if (f.size() == 4) m.baseColor = glm::vec4(float(f[0]), float(f[1]), float(f[2]), float(f[3]));
    if (gm.alphaMode == "MASK") {
      m.alphaMask = true;
      m.alphaCutoff = float(gm.alphaCutoff);
    } else if (gm.alphaMode == "BLEND") {
      // Depth shadow maps store one depth per texel, so blended surfaces are approximated as a mask
      // with the default cutoff (0.5): texels at least half opaque cast shadows.
      m.alphaMask = true;
      m.alphaCutoff = 0.5f;
      m.alphaBlend = true;  // deep shadow maps and the reference attenuate by alpha instead
    }
    m.doubleSided = gm.doubleSided;
    const int tex = gm.pbrMetallicRoughness.baseColorTexture.index;
    if (tex >= 0) m.baseColorTexture = textureIndex(tex, mw + ".baseColorTexture");
    scene_.materials.push_back(m);
    materialCache_[gltfMaterial] = int(scene_.materials.size() - 1);
    return int(scene_.materials.size() - 1);
  }

  int textureIndex(int tex, const std::string& where) {
    if (size_t(tex) >= model_.textures.size()) fail(where + ": texture index " + std::to_string(tex) + " out of range");
    const int source = model_.textures[tex].source;
    if (source < 0) return -1;  // e.g. only an extension source we don't decode: untextured
    if (size_t(source) >= model_.images.size())
      fail(where + ": image index " + std::to_string(source) + " out of range");
    auto it = imageCache_.find(source);
    if (it != imageCache_.end()) return it->second;
    const tinygltf::Image& img = model_.images[source];
    Texture t;
    t.name = !img.uri.empty() ? img.uri : !img.name.empty() ? img.name : "image" + std::to_string(source);
    const std::string iw = "images[" + std::to_string(source) + "] '" + t.name + "'";
    if (img.image.empty() || img.width <= 0 || img.height <= 0) {
      // tinygltf reports unreadable images as warnings and keeps going; here it is an error.
      fail(iw + ": image could not be loaded" + (warn_.empty() ? "" : " (" + warn_ + ")"));
    }
    const int comps = img.component;
    const int bytesPerComp = img.bits == 16 ? 2 : 1;
    if (comps < 1 || comps > 4 || (img.bits != 8 && img.bits != 16)) {
      fail(iw + ": unsupported pixel format (" + std::to_string(comps) + " channels, " + std::to_string(img.bits) +
           " bits)");
    }
    const size_t pixels = size_t(img.width) * size_t(img.height);
    if (img.image.size() < pixels * size_t(comps) * size_t(bytesPerComp)) fail(iw + ": pixel data too short");
    t.width = img.width;
    t.height = img.height;
    t.rgba.resize(pixels * 4);
    for (size_t i = 0; i < pixels; ++i) {
      uint8_t c[4] = {0, 0, 0, 255};
      for (int k = 0; k < comps; ++k) {
        // 16-bit data is little-endian as stb returns it; keep the high byte.
        const size_t off = (i * size_t(comps) + size_t(k)) * size_t(bytesPerComp);
        c[k] = bytesPerComp == 2 ? img.image[off + 1] : img.image[off];
      }
      uint8_t* dst = &t.rgba[i * 4];
      if (comps <= 2) {  // grey (+ alpha)
        dst[0] = dst[1] = dst[2] = c[0];
        dst[3] = comps == 2 ? c[1] : 255;
      } else {
        std::memcpy(dst, c, 4);
      }
    }
    scene_.textures.push_back(std::move(t));
    imageCache_[source] = int(scene_.textures.size() - 1);
    return int(scene_.textures.size() - 1);
  }

  Scene& scene_;
  std::string path_;
  std::string warn_;
  tinygltf::Model model_;
  std::map<std::tuple<int, int, bool>, int> meshCache_;  // (mesh, primitive, mirrored) -> scene mesh
  size_t repairedNormals_ = 0;
  std::map<int, int> materialCache_;
  std::map<int, int> imageCache_;
  int defaultMaterial_ = -1;
};

}  // namespace

void appendGltf(Scene& scene, const std::string& path, const glm::mat4& modelTransform) {
  GltfImporter(scene, path).run(modelTransform);
}

}  // namespace sl
