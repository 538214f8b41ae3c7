#include "deep/deep_curve.h"

#include <algorithm>

namespace sl {

namespace {

// The centre of the deep texel holding uv.
glm::ivec2 texelOf(const DeepState& state, glm::vec2 uv) {
  const int size = state.counts().width();
  return glm::clamp(glm::ivec2(glm::floor(uv * float(size))), glm::ivec2(0), glm::ivec2(size - 1));
}

}  // namespace

glm::vec3 lightRayPoint(const LightView& view, glm::vec2 uv, float d) {
  const glm::mat4 invView = glm::inverse(view.view);
  glm::vec4 q = glm::inverse(view.proj) * glm::vec4(uv * 2.0f - 1.0f, 0.0f, 1.0f);
  q /= q.w;
  const float dist = view.nearPlane + d * (view.farPlane - view.nearPlane);
  const glm::vec3 p = view.perspective ? glm::vec3(q) * (dist / std::max(-q.z, 1e-12f)) : glm::vec3(q.x, q.y, -dist);
  return glm::vec3(invView * glm::vec4(p, 1.0f));
}

std::vector<float> deepTexelCurve(const DeepState& state, glm::vec2 uv, int layer, int samples) {
  if (!state.active() || !state.counts() || samples < 2) return {};
  const int nodes = state.nodes().layers() / std::max(state.counts().layers(), 1);
  const glm::ivec2 t = texelOf(state, uv);
  float count = 0.0f;
  glGetTextureSubImage(state.counts().id(), 0, t.x, t.y, layer, 1, 1, 1, GL_RED, GL_FLOAT, sizeof(count), &count);
  std::vector<glm::vec2> node(static_cast<size_t>(nodes));
  glGetTextureSubImage(state.nodes().id(), 0, t.x, t.y, layer * nodes, 1, 1, nodes, GL_RG, GL_FLOAT,
                       static_cast<GLsizei>(node.size() * sizeof(glm::vec2)), node.data());
  const int n = std::clamp(static_cast<int>(count + 0.5f), 0, nodes);
  std::vector<float> curve;
  for (int s = 0; s < samples; ++s) {
    const float z = static_cast<float>(s) / static_cast<float>(samples - 1);
    float T = 1.0f;
    if (n > 0 && z > node[0].x) {
      T = node[static_cast<size_t>(n - 1)].y;
      for (int k = 1; k < n; ++k) {
        if (z <= node[k].x) {
          const float w = (z - node[k - 1].x) / std::max(node[k].x - node[k - 1].x, 1e-12f);
          T = node[k - 1].y + (node[k].y - node[k - 1].y) * std::clamp(w, 0.0f, 1.0f);
          break;
        }
      }
    }
    curve.push_back(std::clamp(T, 0.0f, 1.0f));
  }
  return curve;
}

std::vector<float> referenceTexelCurve(const ReferenceTracer& tracer, const LightView& view, const DeepState& state,
                                       glm::vec2 uv, int samples) {
  if (!state.active() || !state.counts() || samples < 2) return {};
  const glm::vec2 centre = (glm::vec2(texelOf(state, uv)) + 0.5f) / float(state.counts().width());
  std::vector<float> curve;
  for (int s = 0; s < samples; ++s)
    curve.push_back(tracer.transmittanceToLight(lightRayPoint(view, centre, float(s) / float(samples - 1))));
  return curve;
}

}  // namespace sl
