// Silhouette edges of a scene as the light sees them (Sen, Cammarano and Hanrahan 2003, step 2):
// an edge whose two faces face the light differently, or that has only one face (an open mesh's
// rim). Adjacency is built once per mesh (vertices welded by exact position: glTF splits them at
// normal and uv seams); the edges are re-classified on the CPU when the light or the scene time
// changes, and returned as world-space line segments.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace sl {

struct MeshEdges {
  std::vector<glm::vec3> positions;  // welded, object space
  struct Edge {
    uint32_t a, b;         // welded vertex indices
    int32_t f0, f1;        // adjacent faces; f1 = -1 on an open rim
    bool manifold = true;  // false: three or more faces share it (always treated as silhouette)
  };
  std::vector<Edge> edges;
  std::vector<glm::uvec3> faces;  // welded indices, degenerate triangles dropped
};

MeshEdges buildMeshEdges(const Mesh& mesh);

class SilhouetteEdges {
 public:
  // World-space segments (two points each) of every instance's silhouette edges seen from
  // `light` at `time`. Recomputed only when the scene, its time (if it moves) or the light changed.
  const std::vector<glm::vec3>& update(const Scene& scene, const Light& light, double time);
  bool changed() const { return changed_; }  // the last update recomputed the segments

 private:
  const Scene* scene_ = nullptr;
  size_t triangles_ = 0;
  std::string source_;
  std::vector<MeshEdges> meshes_;
  std::vector<glm::vec3> segments_;
  double time_ = -1e30;
  Light light_;
  bool changed_ = false;
};

// Appends the silhouette segments of one mesh placed by `model`, for a light at `light`.
void appendSilhouettes(const MeshEdges& m, const glm::mat4& model, const Light& light, std::vector<glm::vec3>& out);

}  // namespace sl
