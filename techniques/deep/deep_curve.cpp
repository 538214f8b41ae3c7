#include "deep/deep_curve.h"

#include "part/light_frame.h"

#include <algorithm>

namespace sl {

namespace {

// The deep texel holding layer uv (deep uv through the layer's window, deep_fit.h).
glm::ivec2 texelOf(const DeepState& state, glm::vec2 uv, int layer) {
  const int size = state.counts().width();
  const glm::vec2 deep = state.window(layer).toDeep(uv);
  return glm::clamp(glm::ivec2(glm::floor(deep * float(size))), glm::ivec2(0), glm::ivec2(size - 1));
}

bool insideWindow(const DeepState& state, glm::vec2 uv, int layer) {
  const glm::vec2 deep = state.window(layer).toDeep(uv);
  return deep.x >= 0.0f && deep.y >= 0.0f && deep.x <= 1.0f && deep.y <= 1.0f;
}

}  // namespace

std::vector<float> deepTexelCurve(const DeepState& state, glm::vec2 uv, int layer, int samples) {
  if (!state.active() || !state.counts() || samples < 2) return {};
  const int nodes = state.nodes().layers() / std::max(state.counts().layers(), 1);
  if (!insideWindow(state, uv, layer)) return std::vector<float>(static_cast<size_t>(samples), 1.0f);
  const glm::ivec2 t = texelOf(state, uv, layer);
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

VisibilityCurve DeepState::visibilityCurve(const CurveQuery& q) const {
  VisibilityCurve c{.axis = "light depth", .valueLabel = "transmittance"};
  c.values = deepTexelCurve(*this, glm::vec2(q.uvLayer), static_cast<int>(q.uvLayer.z), q.samples);
  if (c.values.empty()) return {};
  c.truthLabel = "reference (opaque hits included)";
  const int layer = static_cast<int>(q.uvLayer.z);
  const glm::vec2 centre =
      window(layer).toLayer((glm::vec2(texelOf(*this, glm::vec2(q.uvLayer), layer)) + 0.5f) / float(counts().width()));
  for (int s = 0; s < q.samples; ++s)
    c.truthRay.push_back(lightRayPoint(*q.view, centre, float(s) / float(q.samples - 1)));
  return c;
}

}  // namespace sl
