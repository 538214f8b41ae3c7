// The scene model shared by the rasterizer, the ray-traced reference and the UI.
// Meshes live in object space; instances place them (and may move them over time),
// so the renderer can compute per-object previous transforms for reprojection.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

// Thrown for any bad scene input. what() always names the file and the problem.
class SceneError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct Texture {
  std::string name;  // file path or glTF image name, for error messages and UI
  int width = 0;
  int height = 0;
  std::vector<uint8_t> rgba;  // width*height*4, row 0 = top of the image (as stb loads it)
};

struct Material {
  glm::vec4 baseColor{1.0f};
  int baseColorTexture = -1;  // index into Scene::textures, -1 = none
  bool alphaMask = false;     // glTF alphaMode MASK: texels with alpha < cutoff are holes
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
  // Semi-transparent caster (glTF alphaMode BLEND, generated hair): light passes through it
  // attenuated by alpha. Techniques without a transmittance representation treat it as the mask
  // above; the deep shadow map and the reference attenuate.
  bool alphaBlend = false;
};

struct Mesh {
  std::string name;
  std::vector<glm::vec3> positions;  // object space
  std::vector<glm::vec3> normals;    // same count as positions
  std::vector<glm::vec2> uvs;        // same count as positions (zeros when the source has none)
  std::vector<uint32_t> indices;     // triangle list, always indexed after loading
  int material = 0;                  // index into Scene::materials
};

// Rigid motion of an instance over time (seconds), for moving casters and receivers.
struct Motion {
  enum class Type { None, Oscillate, Rotate };
  Type type = Type::None;
  glm::vec3 vector{0.0f};  // Oscillate: displacement amplitude; Rotate: axis
  float period = 4.0f;     // seconds per full cycle
  // Offset transform applied before the instance transform at time t.
  glm::mat4 at(double t) const;
};

struct Instance {
  std::string name;
  int mesh = 0;
  glm::mat4 transform{1.0f};
  Motion motion;
  glm::mat4 transformAt(double t) const { return transform * motion.at(t); }
};

// Lights a scene file may list (each shadowed one costs a technique's maps and passes).
inline constexpr int kMaxSceneLights = 16;

struct Light {
  enum class Type { Directional, Spot, Point };
  Type type = Type::Directional;
  // Spot and point lights sit at `position`; a directional light has none.
  bool positional() const { return type != Type::Directional; }
  glm::vec3 direction{0.0f, -1.0f, 0.0f};  // direction light travels (from light into scene), normalized
  glm::vec3 position{0.0f, 10.0f, 0.0f};   // spot: apex; directional: unused except for radius sampling
  float fovDeg = 60.0f;                    // spot only: full cone angle
  // Area light size (0 = point/hard). Spot: disk radius in world units at `position`, facing
  // `direction`. Directional: tangent of the angular radius (disk radius at unit distance).
  // Point: a sphere of this radius, sampled as the disk facing the receiver.
  float radius = 0.0f;
  // Point: the distance it reaches (points farther away are unlit, in the shading and the
  // reference alike); 0 = no limit.
  float range = 0.0f;
  glm::vec3 color{1.0f};
  // Whether a shadow map is made for it ("shadow": false in the scene file: it lights every point
  // in its range or cone, through casters). The first shadowed light of a list is Scene::light.
  bool shadow = true;
};

// A participating medium: procedural density inside a box or sphere (app/scene/volume_density.h;
// the same function runs in GLSL, shaders/common/volume_density.glsl). Not drawn by the
// rasterizer: it only attenuates light (deep shadow maps, the reference).
struct Volume {
  enum class Shape { Box, Sphere };
  std::string name;
  Shape shape = Shape::Box;
  glm::vec3 center{0.0f};
  glm::vec3 halfSize{0.5f};  // box: half extents; sphere: x = radius
  float extinction = 1.0f;   // sigma_t at full density, per world unit
  float noiseScale = 1.0f;   // noise features per world unit
  float noise = 0.0f;        // 0 = constant density, 1 = fully noise-modulated
  int octaves = 4;
  uint32_t seed = 0;
};

struct Camera {
  std::string name;
  glm::vec3 position{0.0f, 2.0f, 5.0f};
  glm::vec3 target{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fovDeg = 60.0f;  // vertical
  float nearPlane = 0.1f;
  float farPlane = 100.0f;
};

struct CameraKeyframe {
  float time = 0.0f;
  glm::vec3 position{0.0f};
  glm::vec3 target{0.0f};
};

struct CameraPath {
  std::string name;
  std::vector<CameraKeyframe> keys;  // sorted by time, at least 2
  float duration() const { return keys.empty() ? 0.0f : keys.back().time; }
  // Camera at time t (clamped), piecewise linear; fov/near/far come from `base`.
  Camera sample(float t, const Camera& base) const;
};

struct Bounds {
  glm::vec3 min{1e30f};
  glm::vec3 max{-1e30f};
  bool empty() const { return min.x > max.x; }
  void add(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  glm::vec3 center() const { return (min + max) * 0.5f; }
  glm::vec3 extent() const { return max - min; }
};

struct Scene {
  std::string name;        // builtin id or file stem
  std::string sourcePath;  // the file it came from
  std::vector<Mesh> meshes;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Instance> instances;
  // The light the techniques' debug views, the error panel and the bench's visibility metrics
  // show: the first shadowed light of the file's list (or its only light, or the automatic sun).
  Light light;
  // The other lights of the file's list, in order, each shadowed by the technique with its own
  // maps (light.shadow) or unshadowed. The colour sums every light (passes/shade_lights.frag).
  std::vector<Light> otherLights;
  std::vector<Camera> cameras;  // at least one after loading
  std::vector<CameraPath> paths;
  std::vector<Volume> volumes;  // semi-transparent media (scene_effects.h)

  bool hasMotion() const;
  size_t triangleCount() const;
  // World-space bounds of all instances at time t (swept over nothing: just that instant).
  Bounds boundsAt(double t) const;
  // World-space bounds of instance i at time t (empty when it has no valid mesh).
  Bounds instanceBoundsAt(size_t i, double t) const;
  // Bounds that hold the scene at every time: a moving instance's whole sweep (an oscillation's
  // two end positions; a rotation's local bounding sphere), conservatively. A light view fitted
  // to it does not change while objects move, so what was drawn for static parts stays valid.
  Bounds motionEnvelope() const;
  const Camera* findCamera(const std::string& name) const;
  const CameraPath* findPath(const std::string& name) const;
};

// Loads a scene from a builtin id (looked up as <assetsDir>/scenes/<id>.json), a scene .json
// file, or a bare .gltf/.glb (automatic light and camera framing its bounds).
// Throws SceneError naming the file and the problem.
Scene loadScene(const std::string& idOrPath, const std::string& assetsDir);

// Ids of the builtin scenes (the .json files in <assetsDir>/scenes), sorted, `basic` first.
std::vector<std::string> builtinSceneIds(const std::string& assetsDir);

// View and projection of a camera for a given aspect ratio (OpenGL conventions, depth -1..1).
glm::mat4 cameraView(const Camera& c);
glm::mat4 cameraProjection(const Camera& c, float aspect);

}  // namespace sl
