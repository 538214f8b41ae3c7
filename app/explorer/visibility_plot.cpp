#include "explorer/visibility_plot.h"

#include "deep/deep_curve.h"
#include "prefiltered/visibility_curve.h"

#include <memory>

#include <imgui.h>

namespace sl {

namespace {

constexpr int kSamples = 256;

void drawCurve(ImDrawList* list, ImVec2 min, ImVec2 size, const std::vector<float>& v, ImU32 color, float thickness) {
  std::vector<ImVec2> points;
  for (size_t i = 0; i < v.size(); ++i) {
    const float x = static_cast<float>(i) / static_cast<float>(v.size() - 1);
    points.emplace_back(min.x + x * size.x, min.y + (1.0f - std::clamp(v[i], 0.0f, 1.0f)) * size.y);
  }
  list->AddPolyline(points.data(), static_cast<int>(points.size()), color, 0, thickness);
}

// The reference for the deep plot, rebuilt when the scene or its light changes.
const ReferenceTracer& deepPlotTracer(const Scene& scene) {
  static std::unique_ptr<ReferenceTracer> tracer;
  static const Scene* forScene = nullptr;
  static Light forLight;
  const bool sameLight = forLight.direction == scene.light.direction && forLight.position == scene.light.position;
  if (!tracer || forScene != &scene || !sameLight) {
    tracer = std::make_unique<ReferenceTracer>(scene);
    forScene = &scene;
    forLight = scene.light;
  }
  return *tracer;
}

// Deep shadow maps: the stored transmittance of the deep texel under the mouse against light
// depth (orange) over the reference's along the texel's light ray (white).
void drawDeepPlot(const Renderer& renderer, const Viewport& vp, const DeepState& state, const glm::vec3& world,
                  ImVec2 mouse) {
  glm::vec3 uvLayer;
  float receiver = 0;
  if (!state.active() || !renderer.scene() || !mapPointOf(world, vp.lightSpace.primary(), uvLayer, receiver)) return;
  const std::vector<float> curve = deepTexelCurve(state, glm::vec2(uvLayer), 0, kSamples);
  const std::vector<float> truth = referenceTexelCurve(deepPlotTracer(*renderer.scene()), vp.lightSpace.primary(),
                                                       state, glm::vec2(uvLayer), kSamples);
  if (curve.empty() || curve.size() != truth.size()) return;
  ImGui::SetNextWindowPos(ImVec2(mouse.x + 24, mouse.y + 24));
  ImGui::Begin("transmittance vs light depth", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  ImGui::Text("%s at map uv %.3f, %.3f", vp.technique.presetId.c_str(), uvLayer.x, uvLayer.y);
  const ImVec2 size(320, 140), min = ImGui::GetCursorScreenPos();
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddRectFilled(min, ImVec2(min.x + size.x, min.y + size.y), IM_COL32(20, 20, 24, 255));
  const float rx = min.x + std::clamp(receiver, 0.0f, 1.0f) * size.x;
  list->AddLine(ImVec2(rx, min.y), ImVec2(rx, min.y + size.y), IM_COL32(150, 150, 150, 255));
  drawCurve(list, min, size, truth, IM_COL32(255, 255, 255, 255), 2.0f);
  drawCurve(list, min, size, curve, IM_COL32(255, 120, 60, 255), 1.5f);
  ImGui::Dummy(size);
  ImGui::Text("white: reference (opaque hits included), orange: stored nodes; grey: this pixel's depth %.3f", receiver);
  ImGui::End();
}

}  // namespace

void drawVisibilityPlot(ShaderLibrary& shaders, const Renderer& renderer, const Viewport& vp,
                        const MagnifierTarget& target, ImVec2 mouse) {
  const auto* deep = dynamic_cast<const DeepState*>(vp.representation.get());
  const auto* state = dynamic_cast<const MomentMapState*>(vp.representation.get());
  if ((!state && !deep) || !target.valid() || !renderer.hasFreshGBuffer()) return;
  // The pixel under the mouse in the rendered frame (GL rows bottom-up).
  const float fx = (mouse.x - target.imageMin.x) / (target.imageMax.x - target.imageMin.x);
  const float fy = (mouse.y - target.imageMin.y) / (target.imageMax.y - target.imageMin.y);
  const int px = std::clamp(static_cast<int>(fx * target.textureWidth), 0, target.textureWidth - 1);
  const int py = std::clamp(static_cast<int>((1.0f - fy) * target.textureHeight), 0, target.textureHeight - 1);
  float pos[4] = {0, 0, 0, 0};
  glGetTextureSubImage(renderer.gPosition().id(), 0, px, py, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof(pos), pos);
  glm::vec3 uvLayer;
  float receiver = 0;
  if (deep) {
    if (pos[3] >= 0.5f) drawDeepPlot(renderer, vp, *deep, glm::vec3(pos[0], pos[1], pos[2]), mouse);
    return;
  }
  if (pos[3] < 0.5f || !mapPointOf(glm::vec3(pos[0], pos[1], pos[2]), vp.lightSpace.primary(), uvLayer, receiver))
    return;
  const int width = vp.technique.params.i("filter.width");
  const std::vector<float> truth = trueCurve(*state->depthTexture(), uvLayer, width, kSamples);
  const std::vector<float> curve = reconstructedCurve(shaders, vp.technique, *state, uvLayer, kSamples);
  if (curve.size() != truth.size()) return;

  ImGui::SetNextWindowPos(ImVec2(mouse.x + 24, mouse.y + 24));
  ImGui::Begin("visibility vs receiver depth", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  ImGui::Text("%s at map uv %.3f, %.3f", vp.technique.presetId.c_str(), uvLayer.x, uvLayer.y);
  const ImVec2 size(320, 140), min = ImGui::GetCursorScreenPos();
  ImDrawList* list = ImGui::GetWindowDrawList();
  list->AddRectFilled(min, ImVec2(min.x + size.x, min.y + size.y), IM_COL32(20, 20, 24, 255));
  const float rx = min.x + std::clamp(receiver, 0.0f, 1.0f) * size.x;
  list->AddLine(ImVec2(rx, min.y), ImVec2(rx, min.y + size.y), IM_COL32(150, 150, 150, 255));
  drawCurve(list, min, size, truth, IM_COL32(255, 255, 255, 255), 2.0f);
  drawCurve(list, min, size, curve, IM_COL32(255, 120, 60, 255), 1.5f);
  ImGui::Dummy(size);
  ImGui::Text("white: true (box of %d), orange: reconstruction; grey: this pixel's depth %.3f", width, receiver);
  ImGui::End();
}

}  // namespace sl
