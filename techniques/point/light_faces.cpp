#include "point/light_faces.h"

#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// A cube face's corners in the order of a frustum's (x + 2y bits of the face's right and up).
LightFace cubeFace(const glm::vec3& axis, const glm::vec3& up) {
  const glm::vec3 right = glm::normalize(glm::cross(axis, up));
  const glm::vec3 trueUp = glm::cross(right, axis);
  LightFace f{axis, up, {}};
  for (int y = -1; y <= 1; y += 2)
    for (int x = -1; x <= 1; x += 2) f.corners.push_back(axis + float(x) * right + float(y) * trueUp);
  return f;
}

FaceSet makeCube() {
  return {"cube",
          {cubeFace({1, 0, 0}, {0, -1, 0}), cubeFace({-1, 0, 0}, {0, -1, 0}), cubeFace({0, 1, 0}, {0, 0, 1}),
           cubeFace({0, -1, 0}, {0, 0, -1}), cubeFace({0, 0, 1}, {0, -1, 0}), cubeFace({0, 0, -1}, {0, -1, 0})}};
}

// A regular tetrahedron's face normals: one straight down (a lamp's ground in one face), three
// 19.47 degrees above the horizon, 120 degrees apart; any two at dot -1/3. The corners of face i's
// region are the tetrahedron's vertices seen from its centre, -n_j for j != i.
FaceSet makeTetrahedron() {
  const float s = std::sqrt(8.0f) / 3.0f;
  std::vector<glm::vec3> normals = {{0, -1, 0}};
  for (int k = 0; k < 3; ++k) {
    const float a = glm::radians(90.0f + 120.0f * k);
    normals.push_back({s * std::cos(a), 1.0f / 3.0f, s * std::sin(a)});
  }
  FaceSet set{"tetrahedron", {}};
  for (size_t i = 0; i < normals.size(); ++i) {
    LightFace f{normals[i], i == 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0), {}};
    for (size_t j = 0; j < normals.size(); ++j)
      if (j != i) f.corners.push_back(-normals[j]);
    set.faces.push_back(f);
  }
  return set;
}

// The body a face owns between two distances along its axis, as 8 corners indexed like a
// frustum's (a triangle's third corner doubled: clipCornersToPlanes accepts collapsed faces).
std::vector<glm::vec3> faceRegion(const LightFace& face, const glm::vec3& apex, float near, float far) {
  std::vector<glm::vec3> dirs = face.corners;
  if (dirs.size() == 3) dirs.push_back(dirs[2]);
  std::vector<glm::vec3> out;
  for (float dist : {near, far})
    for (const glm::vec3& d : dirs) out.push_back(apex + d * (dist / glm::dot(d, face.axis)));
  return out;
}

// The square field of view (degrees) that holds the face's region in `view` (its roll included).
float enclosingFovDeg(const LightFace& face, const glm::mat4& view) {
  float halfTan = 0.0f;
  for (const glm::vec3& c : face.corners) {
    const glm::vec3 v = glm::mat3(view) * c;
    halfTan = std::max({halfTan, std::abs(v.x / -v.z), std::abs(v.y / -v.z)});
  }
  return glm::degrees(2.0f * std::atan(halfTan * 1.0001f));
}

}  // namespace

float pointLightFar(const Light& light, const Bounds& bounds) {
  float far = 0.0f;
  for (const glm::vec3& c : boxCorners(bounds)) far = std::max(far, glm::length(c - light.position));
  if (light.range > 0.0f) far = std::min(far, light.range);
  return std::max(far * 1.01f, 1e-3f);
}

const FaceSet& cubeFaceSet() {
  static const FaceSet set = makeCube();
  return set;
}

const FaceSet& tetrahedronFaceSet() {
  static const FaceSet set = makeTetrahedron();
  return set;
}

int nearestFace(const FaceSet& set, const glm::vec3& d) {
  int best = 0;
  for (int f = 1; f < static_cast<int>(set.faces.size()); ++f)
    if (glm::dot(d, set.faces[f].axis) > glm::dot(d, set.faces[best].axis)) best = f;
  return best;
}

int FaceViews::neededCount() const { return static_cast<int>(std::count(needed.begin(), needed.end(), true)); }

FaceViews faceViews(const FaceSet& set, const Light& light, const LayoutInput& in,
                    const std::vector<ViewPixelBounds>* seen) {
  const Bounds bounds = in.scene->boundsAt(in.time);
  const int size = in.params->i("shadowmap.size");
  const bool snap = in.params->b("layout.snap");
  const float far = pointLightFar(light, bounds);
  // A near plane this close keeps casters touching the light in the map; stored depth is linear,
  // so it costs no precision.
  const float near = far * 1e-4f;
  std::vector<glm::vec4> frustum = frustumPlanes(in.cameraProj * in.cameraView);
  const std::vector<glm::vec4> box = boxPlanes(bounds);
  frustum.insert(frustum.end(), box.begin(), box.end());
  Light faceLight = light;
  faceLight.type = Light::Type::Spot;
  FaceViews out;
  out.space.views.clear();  // a LightSpace starts with one view
  out.space.size = size;
  for (size_t f = 0; f < set.faces.size(); ++f) {
    const LightFace& face = set.faces[f];
    faceLight.direction = face.axis;
    glm::mat4 view = glm::lookAt(light.position, light.position + face.axis, face.up);
    if (in.jitter.rotationRad != 0.0f)
      view = glm::rotate(glm::mat4(1.0f), in.jitter.rotationRad, glm::vec3(0, 0, 1)) * view;
    faceLight.fovDeg = enclosingFovDeg(face, view);
    const std::vector<glm::vec3> region = faceRegion(face, light.position, near, far);
    std::vector<glm::vec3> receivers = clipCornersToPlanes(region, frustum);
    if (seen && f < seen->size())
      receivers = (*seen)[f].valid ? pixelBoundsCorners((*seen)[f], view, size) : std::vector<glm::vec3>{};
    std::vector<glm::vec3> casters = clipCornersToPlanes(region, box);
    const bool needed = !receivers.empty();
    out.needed.push_back(needed);
    if (casters.empty()) casters = region;
    out.space.views.push_back(fitPerspective(faceLight, view, needed ? receivers : region, casters, size, needed, snap,
                                             in.jitter,
                                             /*squareTexels=*/seen == nullptr));
  }
  return out;
}

}  // namespace sl
