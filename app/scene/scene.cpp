// Scene queries, motion, camera paths and camera matrices.
#include "scene/scene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <system_error>

namespace sl {

glm::mat4 Motion::at(double t) const {
  if (type == Type::None || !(period > 0.0f)) return glm::mat4(1.0f);
  // Phase in [0,1) computed in double so long-running sessions don't lose precision.
  const double phase = std::fmod(t / double(period), 1.0);
  const float angle = float(phase * 2.0 * 3.14159265358979323846);
  if (type == Type::Oscillate) {
    return glm::translate(glm::mat4(1.0f), vector * std::sin(angle));
  }
  const float len = glm::length(vector);
  if (!(len > 0.0f)) return glm::mat4(1.0f);
  return glm::rotate(glm::mat4(1.0f), angle, vector / len);
}

Camera CameraPath::sample(float t, const Camera& base) const {
  Camera c = base;
  if (keys.empty()) return c;
  const CameraKeyframe* a = &keys.front();
  const CameraKeyframe* b = a;
  if (t >= keys.back().time) {
    a = b = &keys.back();
  } else if (t > keys.front().time) {
    // First key strictly after t; keys are sorted with increasing times.
    auto it =
        std::upper_bound(keys.begin(), keys.end(), t, [](float v, const CameraKeyframe& k) { return v < k.time; });
    b = &*it;
    a = &*(it - 1);
  }
  const float span = b->time - a->time;
  const float f = span > 0.0f ? (t - a->time) / span : 0.0f;
  c.position = glm::mix(a->position, b->position, f);
  c.target = glm::mix(a->target, b->target, f);
  return c;
}

bool Scene::hasMotion() const {
  return std::any_of(instances.begin(), instances.end(),
                     [](const Instance& i) { return i.motion.type != Motion::Type::None; });
}

size_t Scene::triangleCount() const {
  size_t n = 0;
  for (const Instance& inst : instances) {
    if (inst.mesh >= 0 && size_t(inst.mesh) < meshes.size()) n += meshes[inst.mesh].indices.size() / 3;
  }
  return n;
}

namespace {

// Adds a mesh's vertices, placed by `m`, to the bounds.
void addPlaced(const Mesh& mesh, const glm::mat4& m, Bounds& b) {
  for (const glm::vec3& p : mesh.positions) b.add(glm::vec3(m * glm::vec4(p, 1.0f)));
}

// Where a moving instance can be at any time, in world space (conservative).
void addSweep(const Instance& inst, const Mesh& mesh, Bounds& b) {
  if (inst.motion.type == Motion::Type::Oscillate) {
    // The offset is vector * sin: the box swept between its two ends lies within theirs.
    for (float s : {-1.0f, 1.0f})
      addPlaced(mesh, inst.transform * glm::translate(glm::mat4(1.0f), inst.motion.vector * s), b);
    return;
  }
  // A rotation about the local origin keeps every point within the local sphere of the farthest.
  float r = 0.0f;
  for (const glm::vec3& p : mesh.positions) r = std::max(r, glm::length(p));
  for (int c = 0; c < 8; ++c) {
    const glm::vec3 corner((c & 1) ? r : -r, (c & 2) ? r : -r, (c & 4) ? r : -r);
    b.add(glm::vec3(inst.transform * glm::vec4(corner, 1.0f)));
  }
}

}  // namespace

Bounds Scene::boundsAt(double t) const {
  Bounds b;
  for (const Instance& inst : instances) {
    if (inst.mesh < 0 || size_t(inst.mesh) >= meshes.size()) continue;
    addPlaced(meshes[inst.mesh], inst.transformAt(t), b);
  }
  // Media cast shadows too: light frusta fitted to the bounds must hold them.
  for (const Volume& v : volumes) {
    const glm::vec3 h = v.shape == Volume::Shape::Sphere ? glm::vec3(v.halfSize.x) : v.halfSize;
    b.add(v.center - h);
    b.add(v.center + h);
  }
  return b;
}

Bounds Scene::instanceBoundsAt(size_t i, double t) const {
  Bounds b;
  const Instance& inst = instances.at(i);
  if (inst.mesh < 0 || size_t(inst.mesh) >= meshes.size()) return b;
  addPlaced(meshes[inst.mesh], inst.transformAt(t), b);
  return b;
}

Bounds Scene::motionEnvelope() const {
  Bounds b = boundsAt(0.0);
  for (const Instance& inst : instances)
    if (inst.motion.type != Motion::Type::None && inst.mesh >= 0 && size_t(inst.mesh) < meshes.size())
      addSweep(inst, meshes[inst.mesh], b);
  return b;
}

const Camera* Scene::findCamera(const std::string& cameraName) const {
  for (const Camera& c : cameras) {
    if (c.name == cameraName) return &c;
  }
  return nullptr;
}

const CameraPath* Scene::findPath(const std::string& pathName) const {
  for (const CameraPath& p : paths) {
    if (p.name == pathName) return &p;
  }
  return nullptr;
}

std::vector<std::string> builtinSceneIds(const std::string& assetsDir) {
  namespace fs = std::filesystem;
  std::vector<std::string> ids;
  std::error_code ec;
  for (fs::directory_iterator it(fs::path(assetsDir) / "scenes", ec), end; !ec && it != end; it.increment(ec)) {
    if (it->path().extension() == ".json") ids.push_back(it->path().stem().string());
  }
  std::sort(ids.begin(), ids.end(), [](const std::string& a, const std::string& b) {
    if ((a == "basic") != (b == "basic")) return a == "basic";
    return a < b;
  });
  return ids;
}

glm::mat4 cameraView(const Camera& c) {
  // A camera looking along its up vector (straight down with the default +Y up) has no defined
  // roll: lookAt would divide by zero and every pixel would be NaN. Pick a perpendicular up.
  const glm::vec3 forward = c.target - c.position;
  glm::vec3 up = c.up;
  const float f = glm::length(forward), u = glm::length(up);
  if (f > 0.0f && (!(u > 0.0f) || glm::length(glm::cross(forward / f, up / u)) < 1e-4f))
    up = std::abs(forward.z) < 0.9f * f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
  return glm::lookAt(c.position, c.target, up);
}

glm::mat4 cameraProjection(const Camera& c, float aspect) {
  // glm's default clip space is OpenGL's (depth -1..1) unless GLM_FORCE_DEPTH_ZERO_TO_ONE is set.
  return glm::perspectiveRH_NO(glm::radians(c.fovDeg), aspect, c.nearPlane, c.farPlane);
}

}  // namespace sl
