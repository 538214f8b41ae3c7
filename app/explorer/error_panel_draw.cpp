// The accuracy panel's drawing: status, per-viewport numbers, the error-vs-time chart with its
// Pareto front (state and measurement are in error_panel.cpp).
#include "explorer/error_panel.h"

#include "explorer/explorer_state.h"
#include "render/renderer.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace sl {

namespace {

const ImVec4 kDim(0.65f, 0.65f, 0.68f, 1.0f);
const ImVec4 kFalseShadow(1.0f, 0.60f, 0.20f, 1.0f);  // the error view's orange
const ImVec4 kFalseLight(0.35f, 0.62f, 1.0f, 1.0f);   // and blue
const ImU32 kViewportColors[4] = {IM_COL32(255, 205, 80, 255), IM_COL32(90, 205, 255, 255),
                                  IM_COL32(140, 225, 120, 255), IM_COL32(240, 130, 210, 255)};
const ImU32 kOldPoint = IM_COL32(150, 150, 160, 255);

void dashedLine(ImDrawList* d, ImVec2 a, ImVec2 b, ImU32 col, float thickness, float dash = 5.0f) {
  const float dx = b.x - a.x, dy = b.y - a.y;
  const float len = std::sqrt(dx * dx + dy * dy);
  if (len <= 0) return;
  for (float s = 0; s < len; s += 2 * dash) {
    const float e = std::min(len, s + dash);
    d->AddLine(ImVec2(a.x + dx * s / len, a.y + dy * s / len), ImVec2(a.x + dx * e / len, a.y + dy * e / len), col,
               thickness);
  }
}

const ImU32 kChartGrid = IM_COL32(60, 60, 68, 255);
const ImU32 kChartLabel = IM_COL32(170, 170, 178, 255);
const ImU32 kChartFront = IM_COL32(230, 230, 230, 200);

constexpr int kColumns = 8;  // of the accuracy table

void setUpAccuracyColumns() {
  // Short headers: at the panel's default width "f.shadow" was cut off.
  const char* headers[kColumns] = {"#", "wrong", "image", "dark", "leak", "rmse", "NaN", "ms"};
  const char* tips[kColumns] = {
      "Viewport (colour of its points in the chart)",
      "Wrong pixels, % of covered pixels: |visibility - truth| > 30/255.\n"
      "Against the hard (point-light) reference a filtered or soft technique's intended penumbra\n"
      "counts as wrong: judge PCF, the pre-filtered maps and PCSS by 'image' and 'rmse' instead.",
      "Image-wrong pixels, % of covered pixels: the shaded colour differs from the same shading\n"
      "with the truth's visibility by more than 30/255 in R, G or B (Scherzer et al.'s figure 3).\n"
      "Lower than 'wrong' where the shading hides a visibility error: grazing light (small N.L),\n"
      "dark albedo. The one to judge a filtered or soft technique by.",
      "False shadow, %: dark where the truth is lit (orange in the error view)",
      "False light, %: lit where the truth is dark: light leaks (blue in the error view)",
      "Root mean square visibility error over covered pixels",
      "Non-finite (NaN/Inf) visibility values, counted as wrong",
      "ms per frame of this viewport's own passes (names ending in [v]): not the debug views\n"
      "('view.*') and not the shared G-buffer, which techniques do not read (it is drawn for\n"
      "debug views and the reference), so the figure does not depend on what else is shown.\n"
      "Median of the last 30 frames (see Timings for the passes)."};
  const float weights[kColumns] = {0.4f, 1.0f, 1.0f, 1.1f, 1.0f, 1.0f, 0.7f, 1.0f};
  for (int c = 0; c < kColumns; ++c) ImGui::TableSetupColumn(headers[c], 0, weights[c]);
  ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
  for (int c = 0; c < kColumns; ++c) {
    ImGui::TableSetColumnIndex(c);
    ImGui::TableHeader(headers[c]);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tips[c]);
  }
}

// Columns 1-6 of a measured viewport; greyed when the measurement is of an earlier view.
void drawMetricCells(const ErrorMetrics& m, const ImageErrorMetrics& image, bool current) {
  auto cell = [&](int column, const char* text, const ImVec4* color) {
    ImGui::TableSetColumnIndex(column);
    if (!current)
      ImGui::TextDisabled("%s", text);
    else if (color)
      ImGui::TextColored(*color, "%s", text);
    else
      ImGui::TextUnformatted(text);
  };
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f%%", m.wrongPixelPct);
  cell(1, buf, nullptr);
  if (std::isfinite(image.imageWrongPct))
    std::snprintf(buf, sizeof buf, "%.2f%%", image.imageWrongPct);
  else
    std::snprintf(buf, sizeof buf, "-");
  cell(2, buf, nullptr);
  std::snprintf(buf, sizeof buf, "%.2f%%", m.falseShadowPct);
  cell(3, buf, &kFalseShadow);
  std::snprintf(buf, sizeof buf, "%.2f%%", m.falseLightPct);
  cell(4, buf, &kFalseLight);
  std::snprintf(buf, sizeof buf, "%.3f", m.rmse);
  cell(5, buf, nullptr);
  std::snprintf(buf, sizeof buf, "%lld", m.nonfinite);
  cell(6, buf, m.nonfinite > 0 ? &kFalseShadow : nullptr);
}

// The ms column: timed every frame, so never greyed like the error columns.
void drawCostCell(const MedianWindow& ownMs, const MedianWindow& gbufferMs, bool timing) {
  ImGui::TableSetColumnIndex(7);
  const double own = ownMs.median(), gb = gbufferMs.median();
  if (own >= 0) {
    ImGui::Text("%.2f", own);
    if (ImGui::IsItemHovered()) {
      if (gb >= 0)
        ImGui::SetTooltip("%.2f ms own passes, median of %zu frames (the shared G-buffer, %.2f ms, not included)", own,
                          ownMs.count(), gb);
      else
        ImGui::SetTooltip("%.2f ms own passes, median of %zu frames", own, ownMs.count());
    }
  } else {
    ImGui::TextDisabled("-");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", timing ? "no timed pass yet" : "Timings > Time passes is off");
  }
}

// Returns whether "clear" was clicked.
bool drawChartHeading() {
  ImGui::TextUnformatted("Error vs time, this session");
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "One point per configuration (technique + changed parameters) measured this\n"
        "session: the median error of its last 5 measurements and the median ms (own passes)\n"
        "of its last 64, so a point holds still while readings jitter (and still follows a\n"
        "technique that converges). Dashed: the Pareto front, configurations\n"
        "that no other is both faster and more accurate than. Numbered points are what\n"
        "the viewports show now; grey ones were tried earlier (possibly from another\n"
        "camera: compare points measured at the same view).");
  ImGui::SameLine(ImGui::GetContentRegionAvail().x - 40.0f);
  return ImGui::SmallButton("clear");
}

// The chart's plot rectangle and axes, shared by the drawing steps below.
struct ChartCanvas {
  ImDrawList* d = nullptr;
  ImVec2 origin;
  float line = 0, left = 0, right = 0, top = 0, bottom = 0;
  bool hovered = false;
  ChartAxis xAxis, yAxis;
  ImVec2 toScreen(double ms, double err) const {
    return ImVec2(left + float(xAxis.toUnit(ms)) * (right - left), bottom - float(yAxis.toUnit(err)) * (bottom - top));
  }
};

// Reserves the chart's space (an invisible button, so hovering it can be told apart) and fits
// the axes to the points.
ChartCanvas placeChartCanvas(const std::vector<ChartPoint>& points) {
  ChartCanvas c;
  const float width = ImGui::GetContentRegionAvail().x;
  const float height = std::max(160.0f, std::min(240.0f, width * 0.55f));
  c.origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("chart", ImVec2(width, height));
  c.hovered = ImGui::IsItemHovered();
  c.d = ImGui::GetWindowDrawList();
  c.line = ImGui::GetTextLineHeight();
  c.left = c.origin.x + 44.0f, c.right = c.origin.x + width - 8.0f;
  c.top = c.origin.y + 6.0f, c.bottom = c.origin.y + height - 2.0f * c.line - 4.0f;
  c.d->AddRectFilled(c.origin, ImVec2(c.origin.x + width, c.origin.y + height), IM_COL32(24, 24, 28, 255), 3.0f);
  c.d->AddRect(ImVec2(c.left, c.top), ImVec2(c.right, c.bottom), IM_COL32(90, 90, 100, 255));

  double msMin = 1e30, msMax = -1e30, errMin = 1e30, errMax = -1e30;
  for (const ChartPoint& p : points) {
    msMin = std::min(msMin, p.ms), msMax = std::max(msMax, p.ms);
    errMin = std::min(errMin, p.wrongPct), errMax = std::max(errMax, p.wrongPct);
  }
  c.xAxis = chooseChartAxis(msMin, msMax, 0.01);
  c.yAxis = chooseChartAxis(errMin, errMax, 0.01);
  return c;
}

void drawChartAxes(const ChartCanvas& c) {
  ImDrawList* d = c.d;
  for (double t : c.xAxis.ticks()) {
    const float x = c.toScreen(t, 0).x;
    d->AddLine(ImVec2(x, c.top), ImVec2(x, c.bottom), kChartGrid);
    const std::string s = formatTick(t);
    const float w = ImGui::CalcTextSize(s.c_str()).x;
    d->AddText(ImVec2(std::min(x - w * 0.5f, c.right - w), c.bottom + 2.0f), kChartLabel, s.c_str());
  }
  for (double t : c.yAxis.ticks()) {
    const float y = c.toScreen(0, t).y;
    d->AddLine(ImVec2(c.left, y), ImVec2(c.right, y), kChartGrid);
    const std::string s = formatTick(t);
    const float w = ImGui::CalcTextSize(s.c_str()).x;
    d->AddText(ImVec2(c.left - w - 4.0f, y - c.line * 0.5f), kChartLabel, s.c_str());
  }
  const std::string xLabel = std::string("ms per frame") + (c.xAxis.log ? " (log)" : "");
  const std::string yLabel = std::string("wrong %") + (c.yAxis.log ? " (log)" : "");
  d->AddText(ImVec2((c.left + c.right - ImGui::CalcTextSize(xLabel.c_str()).x) * 0.5f, c.bottom + c.line + 2.0f),
             kChartLabel, xLabel.c_str());
  d->AddText(ImVec2(c.origin.x + 4.0f, c.bottom + c.line + 2.0f), kChartLabel, yLabel.c_str());
}

// A dashed staircase: the best error available for a given time budget.
void drawParetoFront(const ChartCanvas& c, const std::vector<ChartPoint>& points, const std::vector<size_t>& front) {
  for (size_t k = 0; k < front.size(); ++k) {
    const ImVec2 p = c.toScreen(points[front[k]].ms, points[front[k]].wrongPct);
    const float xEnd = k + 1 < front.size() ? c.toScreen(points[front[k + 1]].ms, 0).x : c.right;
    dashedLine(c.d, p, ImVec2(xEnd, p.y), kChartFront, 1.5f);
    if (k + 1 < front.size()) {
      const ImVec2 q = c.toScreen(points[front[k + 1]].ms, points[front[k + 1]].wrongPct);
      dashedLine(c.d, ImVec2(xEnd, p.y), ImVec2(xEnd, q.y), kChartFront, 1.5f);
    }
  }
}

// The configurations shown now in their viewport's colour and number, others grey. Returns the
// point nearest the mouse (within 8 px), or -1.
int drawChartPoints(const ChartCanvas& c, const std::vector<ChartPoint>& points,
                    const std::vector<std::string>& shownConfigs) {
  ImDrawList* d = c.d;
  const ImVec2 mouse = ImGui::GetIO().MousePos;
  int hovered = -1;
  float hoveredDist = 8.0f * 8.0f;
  d->PushClipRect(ImVec2(c.left - 6, c.top - 6), ImVec2(c.right + 6, c.bottom + 6), true);
  for (size_t n = 0; n < points.size(); ++n) {
    const ChartPoint& p = points[n];
    const ImVec2 s = c.toScreen(p.ms, p.wrongPct);
    int shownIn = -1;
    for (int i = 0; i < 4; ++i)
      if (!shownConfigs[size_t(i)].empty() && shownConfigs[size_t(i)] == p.config) shownIn = i;
    if (shownIn >= 0) {
      d->AddCircleFilled(s, 5.0f, kViewportColors[shownIn]);
      // The viewport's number and its preset, as the viewport's title names it.
      const std::string label = std::to_string(shownIn + 1) + " " + p.config.substr(0, p.config.find(' '));
      d->AddText(ImVec2(s.x + 6.0f, s.y - c.line - 1.0f), kViewportColors[shownIn], label.c_str());
    } else {
      d->AddCircle(s, 4.0f, kOldPoint, 0, 1.5f);
    }
    const float dx = s.x - mouse.x, dy = s.y - mouse.y;
    if (c.hovered && dx * dx + dy * dy < hoveredDist) {
      hoveredDist = dx * dx + dy * dy;
      hovered = int(n);
    }
  }
  d->PopClipRect();
  return hovered;
}

}  // namespace

void ErrorPanel::drawPanel(ExplorerState& state) {
  if (!ImGui::CollapsingHeader("Accuracy vs ray-traced truth", ImGuiTreeNodeFlags_DefaultOpen)) return;
  drawStatus();
  drawAccuracyTable(state);
  if (currentRef_ == 0 && std::any_of(std::begin(viewports_), std::end(viewports_),
                                      [](const ViewportAccuracy& v) { return v.haveMetrics; }))
    ImGui::TextDisabled("(grey: measured at the previous resting view)");
  drawChart(state);
}

// Tracing, ready, or why nothing is measured.
void ErrorPanel::drawStatus() const {
  const Reference* ref = currentReference();
  if (active_) {
    const JobProgress job = activeProgress();
    char overlay[96];
    std::snprintf(overlay, sizeof overlay, "%s %.0f%%  (%.1f s)", job.building ? "building BVH" : "tracing",
                  job.fraction * 100.0f, job.seconds);
    ImGui::ProgressBar(job.fraction, ImVec2(-1, 0), overlay);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "Ray-traced reference (Embree, %d light samples for area lights, %d threads)\n"
          "of this %dx%d frame, on a worker thread. Moving the camera cancels it.",
          job.samples, job.threads, job.width, job.height);
  } else if (!jobError_.empty() && haveFailed_ && sameRestKey(failedKey_, rest_.key())) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.38f, 0.35f, 1.0f));
    ImGui::TextWrapped("reference failed: %s", jobError_.c_str());
    ImGui::PopStyleColor();
  } else if (ref) {
    ImGui::TextDisabled("reference %dx%d traced in %.1f s (BVH %.2f s)", ref->key.width, ref->key.height,
                        ref->traceMs / 1000.0, ref->buildMs / 1000.0);
  } else if (!rendered_) {
    ImGui::TextDisabled("no frame rendered");
  } else if (!rest_.resting()) {
    const RestKeyChange& c = rest_.lastChange();
    const char* why = c.time    ? "scene moving: pause time (Scene panel) to measure"
                      : c.size  ? "window resized: waiting for it to settle"
                      : c.scene ? "new scene: waiting for the camera to rest"
                                : "camera moving: let it rest to measure";
    ImGui::TextDisabled("%s", why);
  } else {
    ImGui::TextDisabled("waiting for the previous trace to stop");
  }
}

void ErrorPanel::drawAccuracyTable(const ExplorerState& state) const {
  const ImGuiTableFlags flags =
      ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable("accuracy", kColumns, flags)) return;
  setUpAccuracyColumns();
  for (int i = 0; i < state.viewportCount && i < int(state.slots.size()) && i < 4; ++i)
    if (state.slots[size_t(i)].viewport) drawAccuracyRow(i);
  ImGui::EndTable();
}

void ErrorPanel::drawAccuracyRow(int i) const {
  const ViewportAccuracy& va = viewports_[i];
  const bool current =
      va.haveMetrics && currentRef_ != 0 && va.referenceId == currentRef_ && va.config == va.timedConfig;
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::ColorConvertU32ToFloat4(kViewportColors[i]));
  ImGui::Text("%d", i + 1);
  ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", va.timedConfig.c_str());
  if (va.haveMetrics) {
    drawMetricCells(va.metrics, va.image, current);
  } else {
    for (int c = 1; c <= 6; ++c) {
      ImGui::TableSetColumnIndex(c);
      ImGui::TextDisabled("-");
    }
  }
  drawCostCell(va.ownMs, va.gbufferMs, timing_);
  // A scene of several lights: a row per other shadowed light, its visibility against the
  // reference traced toward it (the image column, which sums every light, is the row above's).
  if (!va.haveMetrics) return;
  for (size_t k = 0; k < va.otherLights.size(); ++k) {
    if (!va.otherLights[k].shadowed) continue;
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::TextDisabled("L%zu", k + 2);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("viewport %d, light %zu (Scene section) against the reference traced toward it", i + 1, k + 2);
    drawMetricCells(va.otherLights[k].error, ImageErrorMetrics{std::numeric_limits<double>::quiet_NaN(), 0}, current);
  }
}

// The config each of the 4 viewport slots shows, "" for slots without a viewport.
std::vector<std::string> ErrorPanel::shownConfigs(const ExplorerState& state) const {
  std::vector<std::string> configs(4);
  for (int i = 0; i < state.viewportCount && i < 4; ++i)
    if (state.slots.size() > size_t(i) && state.slots[size_t(i)].viewport)
      configs[size_t(i)] = viewports_[i].timedConfig;
  return configs;
}

void ErrorPanel::drawChart(const ExplorerState& state) {
  if (drawChartHeading()) points_.clear();
  const ChartCanvas canvas = placeChartCanvas(points_);
  drawChartAxes(canvas);
  if (points_.empty()) {
    const char* msg = "no measurement yet: rest the camera";
    const ImVec2 s = ImGui::CalcTextSize(msg);
    canvas.d->AddText(ImVec2((canvas.left + canvas.right - s.x) * 0.5f, (canvas.top + canvas.bottom - s.y) * 0.5f),
                      kChartLabel, msg);
    return;
  }
  const std::vector<size_t> front = paretoFront(points_);
  drawParetoFront(canvas, points_, front);
  const int hovered = drawChartPoints(canvas, points_, shownConfigs(state));
  if (hovered < 0) return;
  const ChartPoint& p = points_[size_t(hovered)];
  const bool onFront = std::find(front.begin(), front.end(), size_t(hovered)) != front.end();
  ImGui::SetTooltip("%s\n%.2f ms per frame (median of %zu readings), %.2f%% wrong pixels, %.2f%% image-wrong%s",
                    p.config.c_str(), p.ms, p.msReadings.size(), p.wrongPct, p.imageWrongPct,
                    onFront ? "\non the Pareto front" : "");
}

}  // namespace sl
