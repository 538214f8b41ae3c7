#include "explorer/visibility_plot.h"

#include "explorer/plot_window.h"
#include "part/light_frame.h"
#include "reference/reference.h"

#include <algorithm>
#include <cstdio>
#include <memory>

#include <imgui.h>

namespace sl {

namespace {

constexpr int kSamples = 256;

// The reference for curves traced along a light ray (deep maps), rebuilt when the scene or its light changes.
const ReferenceTracer& plotTracer(const Scene& scene) {
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

// The truth a curve is judged by: its own, or the reference traced along its light ray.
std::vector<float> curveTruth(const Scene& scene, const VisibilityCurve& c) {
  if (!c.truth.empty() || c.truthRay.empty()) return c.truth;
  std::vector<float> out;
  const ReferenceTracer& tracer = plotTracer(scene);
  for (const glm::vec3& p : c.truthRay) out.push_back(tracer.transmittanceToLight(p));
  return out;
}

// The curve of shown[i]'s representation at a world point, in its own map.
VisibilityCurve curveAt(ShaderLibrary& shaders, const Viewport& vp, const glm::vec3& world, float* receiver) {
  CurveQuery q{.shaders = &shaders, .technique = &vp.technique, .view = &vp.lightSpace.primary(), .samples = kSamples};
  float depth = 0;
  if (!mapPointOf(world, vp.lightSpace.primary(), q.uvLayer, depth)) return {};
  if (receiver) *receiver = depth;
  return vp.representation->visibilityCurve(q);
}

// The surface point under the mouse in the rendered frame (GL rows bottom-up); every viewport
// shares the camera, hence this G-buffer. False over the background.
bool worldUnderMouse(const Renderer& renderer, const MagnifierTarget& target, ImVec2 mouse, glm::vec3& world) {
  const float fx = (mouse.x - target.imageMin.x) / (target.imageMax.x - target.imageMin.x);
  const float fy = (mouse.y - target.imageMin.y) / (target.imageMax.y - target.imageMin.y);
  const int px = std::clamp(static_cast<int>(fx * target.textureWidth), 0, target.textureWidth - 1);
  const int py = std::clamp(static_cast<int>((1.0f - fy) * target.textureHeight), 0, target.textureHeight - 1);
  float pos[4] = {0, 0, 0, 0};
  glGetTextureSubImage(renderer.gPosition().id(), 0, px, py, 0, 1, 1, 1, GL_RGBA, GL_FLOAT, sizeof(pos), pos);
  world = glm::vec3(pos[0], pos[1], pos[2]);
  return pos[3] >= 0.5f;
}

}  // namespace

void drawVisibilityPlot(ShaderLibrary& shaders, const Renderer& renderer, const std::vector<Viewport*>& shown,
                        size_t hovered, const MagnifierTarget& target, ImVec2 mouse) {
  if (hovered >= shown.size() || !target.valid() || !renderer.hasFreshGBuffer() || !renderer.scene()) return;
  glm::vec3 world;
  if (!worldUnderMouse(renderer, target, mouse, world)) return;
  const Viewport& vp = *shown[hovered];
  float receiver = 0;
  const VisibilityCurve mine = curveAt(shaders, vp, world, &receiver);
  if (mine.empty()) return;
  const std::vector<float> truth = curveTruth(*renderer.scene(), mine);
  if (truth.size() != mine.values.size()) return;
  char title[160];
  std::snprintf(title, sizeof title, "%s: %s vs %s", vp.technique.presetId.c_str(), mine.valueLabel.c_str(),
                mine.axis.c_str());
  Plot plot = depthPlot(title, mine.axis, mine.valueLabel, receiver);
  plot.series.push_back(evenlySpacedSeries(mine.truthLabel, glm::vec3(0.0f), 2.0f, truth));
  // The hovered viewport first, then every other shown one with a curve on the same axis.
  std::vector<size_t> order{hovered};
  for (size_t i = 0; i < shown.size(); ++i)
    if (i != hovered) order.push_back(i);
  for (size_t i : order) {
    const VisibilityCurve c = i == hovered ? mine : curveAt(shaders, *shown[i], world, nullptr);
    if (c.axis == mine.axis && c.values.size() == truth.size())
      plot.series.push_back(evenlySpacedSeries(std::to_string(i + 1) + ": " + shown[i]->technique.presetId,
                                               plotColour(plot.series.size() - 1), 1.5f, c.values));
  }
  showPlotWindow((mine.valueLabel + " vs " + mine.axis).c_str(), plot,
                 "black: " + mine.truthLabel + " at viewport " + std::to_string(hovered + 1) +
                     "'s texel; dashed: this pixel's depth; other viewports at the same surface point, each in its "
                     "own map",
                 mouse);
}

}  // namespace sl
