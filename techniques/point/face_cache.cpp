#include "point/face_cache.h"

#include "part/light_frame.h"

namespace sl {
namespace {

// A box wholly outside one of the planes is outside the volume (conservative: a box near a
// corner may be kept as inside, which only redraws a face that did not need it).
bool boxMeetsPlanes(const Bounds& box, const std::vector<glm::vec4>& planes) {
  if (box.empty()) return false;
  const std::vector<glm::vec3> corners = boxCorners(box);
  for (const glm::vec4& plane : planes) {
    bool allOutside = true;
    for (const glm::vec3& c : corners) allOutside = allOutside && glm::dot(glm::vec3(plane), c) + plane.w < 0.0f;
    if (allOutside) return false;
  }
  return true;
}

}  // namespace

bool movingInstanceInView(const Scene& scene, const glm::mat4& viewProj, double a, double b) {
  const std::vector<glm::vec4> planes = frustumPlanes(viewProj);
  for (size_t i = 0; i < scene.instances.size(); ++i) {
    if (scene.instances[i].motion.type == Motion::Type::None) continue;
    if (boxMeetsPlanes(scene.instanceBoundsAt(i, a), planes) || boxMeetsPlanes(scene.instanceBoundsAt(i, b), planes))
      return true;
  }
  return false;
}

std::vector<bool> FaceCache::keep(const std::vector<FaceContent>& now, const std::vector<bool>& needed,
                                  const Scene& scene, double time) const {
  std::vector<bool> out(now.size(), false);
  for (size_t f = 0; f < now.size() && f < held_.size() && f < needed.size(); ++f) {
    const Held& h = held_[f];
    if (!needed[f] || !h.valid || !(h.content == now[f])) continue;
    if (h.time == time || !scene.hasMotion())
      out[f] = true;
    else
      out[f] = now[f].projective && !movingInstanceInView(scene, now[f].viewProj, h.time, time);
  }
  return out;
}

void FaceCache::record(const std::vector<FaceContent>& now, const std::vector<bool>& drawn, bool layersKept,
                       double time) {
  held_.resize(now.size());
  for (size_t f = 0; f < now.size(); ++f) {
    if (f < drawn.size() && drawn[f])
      held_[f] = Held{now[f], time, true};
    else if (!layersKept)
      held_[f].valid = false;
  }
}

}  // namespace sl
