// drawPlotWidget, the live dp/ds plot and its window (see plot_window.h).
#include "explorer/plot_window.h"

#include "plot/dpds.h"
#include "technique.h"

#include <algorithm>
#include <cmath>

namespace sl {
namespace {

ImU32 toImU32(glm::vec3 c) {
  c = plotColourOnDark(c);  // the window is dark
  return ImGui::ColorConvertFloat4ToU32(ImVec4(c.r, c.g, c.b, 1.0f));
}

// The reference layouts the survey's error-analysis slides compare.
const std::vector<std::pair<std::string, Technique>>& referenceLayouts() {
  static const std::vector<std::pair<std::string, Technique>> list = [] {
    std::vector<std::pair<std::string, Technique>> out;
    for (const char* id : {"uniform", "psm", "lispsm", "logpsm", "cascaded"}) out.emplace_back(id, makeTechnique(id));
    return out;
  }();
  return list;
}

}  // namespace

std::vector<ImVec2> flowLegend(const std::vector<float>& entryWidths, float width, float lineHeight) {
  std::vector<ImVec2> out;
  float x = 0.0f, y = 0.0f;
  for (float w : entryWidths) {
    if (x > 0.0f && x + w > width) x = 0.0f, y += lineHeight;
    out.push_back(ImVec2(x, y));
    x += w;
  }
  return out;
}

void drawPlotWidget(const Plot& plot, ImVec2 size) {
  const PlotFrame f = resolvePlot(plot);
  ImDrawList* list = ImGui::GetWindowDrawList();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float line = ImGui::GetTextLineHeight();
  // The legend goes right of the plot when its widest name fits in 40 % of the width, else in
  // rows under it (a narrow plot strip cut the names at its edge, #23).
  float widest = 0.0f;
  for (const PlotSeries& s : plot.series) widest = std::max(widest, ImGui::CalcTextSize(s.label.c_str()).x);
  const float entryW = widest + line * 2.0f;
  const bool legendBelow = entryW > size.x * 0.4f;
  // Below: entries flow left to right and wrap, each as wide as its own name.
  std::vector<float> widths;
  for (const PlotSeries& s : plot.series) widths.push_back(ImGui::CalcTextSize(s.label.c_str()).x + line * 2.0f);
  const std::vector<ImVec2> flow = flowLegend(widths, size.x, line);
  const int rows = legendBelow && !flow.empty() ? int(flow.back().y / line) + 1 : 0;
  const float left = origin.x + ImGui::CalcTextSize("0.001").x + 6.0f;
  const float right = origin.x + size.x - (legendBelow ? line * 0.5f : entryW);
  const float top = origin.y + line * 0.5f, bottom = origin.y + size.y - line * (1.5f + float(rows));
  auto at = [&](glm::vec2 u) { return ImVec2(left + u.x * (right - left), bottom - u.y * (bottom - top)); };
  const ImU32 grid = IM_COL32(60, 62, 70, 255), text = IM_COL32(180, 184, 190, 255);
  list->AddRectFilled(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(20, 20, 24, 255));
  for (const auto& t : f.yTicks) {
    const ImVec2 p = at({0.0f, t.at});
    list->AddLine(ImVec2(left, p.y), ImVec2(right, p.y), grid);
    list->AddText(ImVec2(origin.x, p.y - line * 0.5f), text, t.label.c_str());
  }
  for (const auto& t : f.xTicks) {
    const ImVec2 p = at({t.at, 0.0f});
    const float w = ImGui::CalcTextSize(t.label.c_str()).x;
    list->AddText(ImVec2(std::clamp(p.x - w * 0.5f, origin.x, origin.x + size.x - w), bottom + 2.0f), text,
                  t.label.c_str());
  }
  for (float m : plot.markers) {
    const float x = at(f.unit({m, f.yLo})).x;
    for (float y = top; y < bottom; y += 7.0f)
      list->AddLine(ImVec2(x, y), ImVec2(x, std::min(y + 4.0f, bottom)), IM_COL32(150, 150, 150, 255));
  }
  list->PushClipRect(ImVec2(left, top), ImVec2(right + 1.0f, bottom + 1.0f), true);
  for (const PlotSeries& s : plot.series)
    for (const auto& stroke : f.strokes(s)) {
      std::vector<ImVec2> points;
      for (glm::vec2 u : stroke) points.push_back(at(u));
      list->AddPolyline(points.data(), int(points.size()), toImU32(s.colour), 0, s.width);
    }
  list->PopClipRect();
  list->AddRect(ImVec2(left, top), ImVec2(right, bottom), IM_COL32(115, 117, 128, 255));
  list->PushClipRect(origin, ImVec2(origin.x + size.x, origin.y + size.y), true);
  for (size_t k = 0; k < plot.series.size(); ++k) {
    const ImVec2 p = legendBelow ? ImVec2(origin.x + flow[k].x, bottom + line * 1.3f + flow[k].y)
                                 : ImVec2(right + line * 0.5f, top + float(k) * line);
    const ImU32 c = toImU32(plot.series[k].colour);
    list->AddLine(ImVec2(p.x, p.y + line * 0.5f), ImVec2(p.x + line, p.y + line * 0.5f), c, 2.0f);
    list->AddText(ImVec2(p.x + line * 1.3f, p.y), c, plot.series[k].label.c_str());
  }
  list->PopClipRect();
  ImGui::Dummy(size);
}

void drawPlotCaption(const std::string& text, float width) {
  ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", text.c_str());
  ImGui::PopStyleColor();
  ImGui::PopTextWrapPos();
}

Plot liveDpdsPlot(const ExplorerState& state, int width, int height) {
  if (!state.scene || width <= 0 || height <= 0) return {};
  std::vector<LabelledTechnique> techniques;
  std::vector<std::string> shownIds;
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()); ++i) {
    const Viewport* vp = state.slots[size_t(i)].viewport.get();
    if (!vp) continue;
    shownIds.push_back(vp->technique.presetId);
    techniques.push_back({std::to_string(i + 1) + ": " + vp->technique.presetId, &vp->technique});
  }
  for (const auto& [id, t] : referenceLayouts())
    if (std::find(shownIds.begin(), shownIds.end(), id) == shownIds.end()) techniques.push_back({id, &t});
  return dpdsPlot(dpdsCurves(*state.scene, state.camera.camera(), width, height, techniques, 48),
                  "dp/ds along the view, this camera");
}

void drawDpdsWindow(ExplorerState& state, int renderWidth, int renderHeight, ImVec2 areaMin, ImVec2 areaSize) {
  if (!state.showDpdsPlot) return;
  const float line = ImGui::GetTextLineHeight();
  const ImVec2 size(line * 34.0f, line * 16.0f);
  const float windowW = size.x + ImGui::GetStyle().WindowPadding.x * 2.0f;
  ImGui::SetNextWindowPos(ImVec2(areaMin.x + areaSize.x - windowW - line * 0.5f, areaMin.y + line * 0.5f),
                          ImGuiCond_Appearing);
  ImGui::SetNextWindowBgAlpha(0.92f);
  if (!ImGui::Begin("dp/ds: texel size / pixel size along the view", &state.showDpdsPlot,
                    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::End();
    return;
  }
  drawPlotWidget(liveDpdsPlot(state, renderWidth, renderHeight), size);
  drawPlotCaption(
      "x: view depth (log); y: texel / pixel size along the view (log), 1 = one texel per pixel; "
      "grey: the ideal logarithmic map with viewport 1's texels",
      size.x);
  ImGui::End();
}

}  // namespace sl
