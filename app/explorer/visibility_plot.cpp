#include "explorer/visibility_plot.h"

#include "deep/deep_curve.h"
#include "explorer/plot_window.h"
#include "prefiltered/visibility_curve.h"

#include <memory>

#include <imgui.h>

namespace sl {

namespace {

constexpr int kSamples = 256;

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

Plot depthPlot(const std::string& title, const std::string& x, const std::string& y, float receiver) {
  Plot plot;
  plot.title = title;
  plot.x = {.label = x, .lo = 0.0f, .hi = 1.0f};
  plot.y = {.label = y, .lo = -0.2f, .hi = 1.2f, .ticks = {0.0f, 0.5f, 1.0f}};
  plot.markers = {receiver};
  return plot;
}

void showPlotWindow(const char* name, const Plot& plot, const std::string& caption, ImVec2 mouse) {
  ImGui::SetNextWindowPos(ImVec2(mouse.x + 24, mouse.y + 24));
  ImGui::Begin(name, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  ImGui::TextUnformatted(plot.title.c_str());
  const float line = ImGui::GetTextLineHeight();
  drawPlotWidget(plot, ImVec2(line * 28.0f, line * 10.0f));
  drawPlotCaption(caption, line * 28.0f);
  ImGui::End();
}

// Deep shadow maps: the stored transmittance of the deep texel under the mouse against light
// depth over the reference's along the texel's light ray.
void drawDeepPlot(const Renderer& renderer, const Viewport& vp, const DeepState& state, const glm::vec3& world,
                  ImVec2 mouse) {
  glm::vec3 uvLayer;
  float receiver = 0;
  if (!state.active() || !renderer.scene() || !mapPointOf(world, vp.lightSpace.primary(), uvLayer, receiver)) return;
  const std::vector<float> curve = deepTexelCurve(state, glm::vec2(uvLayer), 0, kSamples);
  const std::vector<float> truth = referenceTexelCurve(deepPlotTracer(*renderer.scene()), vp.lightSpace.primary(),
                                                       state, glm::vec2(uvLayer), kSamples);
  if (curve.empty() || curve.size() != truth.size()) return;
  char title[128];
  std::snprintf(title, sizeof title, "%s at map uv %.3f, %.3f", vp.technique.presetId.c_str(), uvLayer.x, uvLayer.y);
  Plot plot = depthPlot(title, "light depth", "transmittance", receiver);
  plot.series.push_back(evenlySpacedSeries("reference (opaque hits included)", glm::vec3(0.0f), 2.0f, truth));
  plot.series.push_back(evenlySpacedSeries("stored nodes", glm::vec3(1.0f, 0.47f, 0.24f), 1.5f, curve));
  showPlotWindow("transmittance vs light depth", plot, "dashed: this pixel's depth", mouse);
}

}  // namespace

void drawVisibilityPlot(ShaderLibrary& shaders, const Renderer& renderer, const std::vector<Viewport*>& shown,
                        size_t hovered, const MagnifierTarget& target, ImVec2 mouse) {
  if (hovered >= shown.size() || !target.valid() || !renderer.hasFreshGBuffer()) return;
  const Viewport& vp = *shown[hovered];
  const auto* deep = dynamic_cast<const DeepState*>(vp.representation.get());
  const auto* state = dynamic_cast<const MomentMapState*>(vp.representation.get());
  if (!state && !deep) return;
  // The pixel under the mouse in the rendered frame (GL rows bottom-up); every viewport shares
  // the camera, hence this G-buffer.
  const float fx = (mouse.x - target.imageMin.x) / (target.imageMax.x - target.imageMin.x);
  const float fy = (mouse.y - target.imageMin.y) / (target.imageMax.y - target.imageMin.y);
  const int px = std::clamp(static_cast<int>(fx * target.textureWidth), 0, target.textureWidth - 1);
  const int py = std::clamp(static_cast<int>((1.0f - fy) * target.textureHeight), 0, target.textureHeight - 1);
  float pos[4] = {0, 0, 0, 0};
  glGetTextureSubImage(renderer.gPosition().id(), 0, px, py, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof(pos), pos);
  if (pos[3] < 0.5f) return;
  const glm::vec3 world(pos[0], pos[1], pos[2]);
  if (deep) return drawDeepPlot(renderer, vp, *deep, world, mouse);
  glm::vec3 uvLayer;
  float receiver = 0;
  if (!mapPointOf(world, vp.lightSpace.primary(), uvLayer, receiver)) return;
  const int width = vp.technique.params.i("filter.width");
  const std::vector<float> truth = trueCurve(*state->depthTexture(), uvLayer, width, kSamples);
  char title[128];
  std::snprintf(title, sizeof title, "%s at map uv %.3f, %.3f", vp.technique.presetId.c_str(), uvLayer.x, uvLayer.y);
  Plot plot = depthPlot(title, "receiver depth", "visibility", receiver);
  plot.series.push_back(
      evenlySpacedSeries("true (box of " + std::to_string(width) + ")", glm::vec3(0.0f), 2.0f, truth));
  // The hovered viewport first, then every other shown pre-filtered one at the same point.
  std::vector<size_t> order{hovered};
  for (size_t i = 0; i < shown.size(); ++i)
    if (i != hovered) order.push_back(i);
  for (size_t i : order) {
    const auto* other = dynamic_cast<const MomentMapState*>(shown[i]->representation.get());
    glm::vec3 uv;
    float depth = 0;
    if (!other || !mapPointOf(world, shown[i]->lightSpace.primary(), uv, depth)) continue;
    const std::vector<float> curve = reconstructedCurve(shaders, shown[i]->technique, *other, uv, kSamples);
    if (curve.size() == truth.size())
      plot.series.push_back(evenlySpacedSeries(std::to_string(i + 1) + ": " + shown[i]->technique.presetId,
                                               plotColour(plot.series.size() - 1), 1.5f, curve));
  }
  showPlotWindow("visibility vs receiver depth", plot,
                 "white: the lit fraction of viewport " + std::to_string(hovered + 1) +
                     "'s filter box; dashed: this pixel's depth; other viewports at the same surface point, each in "
                     "its own map",
                 mouse);
}

}  // namespace sl
