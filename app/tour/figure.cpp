// renderTourFigure (see figure.h): the step is rendered with the renderer `shadowlab render`
// uses, with a still camera, and each captured frame's images are copied into one CPU image.
#include "tour/figure.h"

#include "explorer/explorer_state.h"
#include "gl/shader_library.h"
#include "render/view_keys.h"
#include "render/renderer.h"
#include "tour/figure_plot.h"
#include "tour/step_plot.h"
#include "technique.h"

#include <algorithm>
#include <cmath>
#include <memory>

namespace sl {
namespace {

const glm::vec3 kBackground{0.09f, 0.09f, 0.1f};
const glm::vec3 kText{0.92f, 0.92f, 0.9f};
const glm::vec3 kDimText{0.7f, 0.72f, 0.75f};
constexpr int kKeyBar = 10;  // colour-key bar height

struct Panel {
  size_t viewport = 0;
  std::string view;  // "" = the colour image
  bool placeholder = false;
  std::string title;
};

struct FigureLayout {
  int margin = 12, panelW = 0, panelH = 0, cellW = 0, cellH = 0, headerH = 0, gridTop = 0, keyH = 0;
  int plotW = 0, plotH = 0;  // the step's plot under the grid (0: none)
  int cols = 0, rows = 0, width = 0, height = 0;
  std::vector<std::string> captionLines;
};

std::vector<Panel> panelsOf(const TourStep& s) {
  std::vector<Panel> panels;
  for (size_t v = 0; v < s.viewports.size(); ++v) {
    const TourViewport& vp = s.viewports[v];
    const std::string name = vp.label.empty() ? vp.technique : vp.label;
    if (!findPreset(vp.technique)) {
      panels.push_back({v, "", true, name + " (not built yet)"});
      continue;
    }
    panels.push_back({v, "", false, name});
    for (const auto& view : vp.views) panels.push_back({v, view, false, name + " \xC2\xB7 " + view});
  }
  return panels;
}

// The view's key when it is a gradient (a categorical key has no bar to draw under a panel).
const ColourKey* gradientKey(const std::string& view) {
  const ColourKey* key = viewColourKey(view);
  return key && !key->stops.empty() ? key : nullptr;
}

FigureLayout layOut(const TourStep& s, const std::vector<Panel>& panels, const FigureFonts& fonts,
                    const FigureOptions& o) {
  FigureLayout l;
  l.panelW = o.panelWidth, l.panelH = o.panelHeight;
  l.cols = static_cast<int>(panels.size());
  l.rows = static_cast<int>(s.frames.size());
  const bool anyKey =
      std::any_of(panels.begin(), panels.end(), [](const Panel& p) { return !p.view.empty() && gradientKey(p.view); });
  const int body = fonts.lineHeight(FigureFonts::Style::Body);
  l.keyH = anyKey ? 4 + kKeyBar + body : 0;
  l.cellW = l.panelW + l.margin;
  l.cellH = body + l.panelH + l.keyH + l.margin;
  l.width = l.margin + l.cols * l.cellW;
  l.headerH = l.margin + fonts.lineHeight(FigureFonts::Style::Title);
  l.gridTop = l.headerH + l.margin / 2;
  if (s.plot.kind != TourPlot::Kind::None) {  // at least 480 wide to be legible: a narrow figure widens
    l.plotW = std::min(std::max(l.width - 2 * l.margin, 480), std::max(2 * l.panelW, 640));
    l.plotH = std::max(l.panelH, 200) + 4 * body;
    l.width = std::max(l.width, l.plotW + 2 * l.margin);
  }
  l.captionLines = fonts.wrap(s.shownCaption(), l.width - 2 * l.margin, FigureFonts::Style::Body);
  l.height = l.gridTop + l.rows * l.cellH + (l.plotH > 0 ? l.plotH + l.margin : 0) +
             static_cast<int>(l.captionLines.size()) * body + l.margin;
  return l;
}

void drawColourKey(RgbaImage& img, const FigureFonts& fonts, const ColourKey& key, int x, int y, int w) {
  for (int i = 0; i < w; ++i)
    img.fillRect(x + i, y, 1, kKeyBar, sampleColourKey(key, w > 1 ? float(i) / float(w - 1) : 0.0f));
  const int ty = y + kKeyBar + 2;
  for (const ColourStop& stop : key.stops) {
    if (stop.label.empty()) continue;
    const int tw = fonts.width(stop.label, FigureFonts::Style::Body);
    const int tx = std::clamp(x + static_cast<int>(stop.position * float(w)) - tw / 2, x, x + w - tw);
    fonts.draw(img, tx, ty, stop.label, FigureFonts::Style::Body, kDimText);
  }
}

std::string frameSuffix(const TourStep& s, int frames) {
  if (s.frames.size() == 1 && frames == 1) return "";
  return " \xC2\xB7 " + std::to_string(frames) + (frames == 1 ? " frame" : " frames");
}

// Copies one capture (a row) of every panel from the viewports' textures.
void captureRow(FigureResult& out, const FigureLayout& l, const FigureFonts& fonts, const TourStep& s,
                const std::vector<Panel>& panels, const std::vector<std::unique_ptr<Viewport>>& vps, int row,
                int frames) {
  const int body = fonts.lineHeight(FigureFonts::Style::Body);
  for (size_t c = 0; c < panels.size(); ++c) {
    const Panel& p = panels[c];
    const int x = l.margin + static_cast<int>(c) * l.cellW, y = l.gridTop + row * l.cellH;
    fonts.draw(out.image, x, y, p.title + frameSuffix(s, frames), FigureFonts::Style::Body, kText);
    const int iy = y + body;
    if (p.placeholder) {
      out.image.fillRect(x, iy, l.panelW, l.panelH, {0.18f, 0.18f, 0.2f});
      fonts.draw(out.image, x + 8, iy + l.panelH / 2 - body / 2, "not built yet", FigureFonts::Style::Body, kDimText);
      continue;
    }
    const Viewport& vp = *vps[p.viewport];
    const Texture2D* tex = p.view.empty() ? vp.colorTexture() : vp.viewTexture(p.view);
    if (!tex) throw std::runtime_error("view '" + p.view + "' was not drawn");
    out.image.blitBottomUp(tex->readRgba8(), l.panelW, l.panelH, x, iy);
    ++out.panels;
    if (!p.view.empty()) {
      if (const ColourKey* key = gradientKey(p.view))
        drawColourKey(out.image, fonts, *key, x, iy + l.panelH + 4, l.panelW);
    }
  }
  for (const auto& vp : vps) {
    if (!vp) continue;
    const std::vector<float> vis = vp->visibilityTexture()->readFloats(2);
    for (size_t i = 0; i < vis.size(); i += 2) out.nonfinitePixels += std::isfinite(vis[i]) ? 0 : 1;
  }
}

}  // namespace

FigureResult renderTourFigure(const Tour& tour, size_t step, ShaderLibrary& shaders, const FigureOptions& o) {
  const TourStep& s = tour.steps.at(step);
  Scene scene = loadStepScene(tour, step, o.assetsDir.empty() ? defaultAssetsDir() : o.assetsDir);
  if (s.setLight) scene.light.direction = directionFromLightAngles(s.lightAngles.x, s.lightAngles.y);
  const Camera camera = stepCamera(tour, step, scene);

  const float bodyPx = std::clamp(o.panelHeight / 16.0f, 11.0f, 20.0f);
  FigureFonts fonts(bodyPx, bodyPx * 1.4f);
  const std::vector<Panel> panels = panelsOf(s);
  const FigureLayout l = layOut(s, panels, fonts, o);
  FigureResult out;
  out.image = RgbaImage(l.width, l.height, kBackground);
  fonts.draw(out.image, l.margin, l.margin / 2, s.title, FigureFonts::Style::Title, kText);

  std::vector<std::unique_ptr<Viewport>> vps(s.viewports.size());
  std::vector<Viewport*> shown;
  for (size_t v = 0; v < s.viewports.size(); ++v) {
    if (!findPreset(s.viewports[v].technique)) continue;
    vps[v] = std::make_unique<Viewport>(makeTechnique(s.viewports[v].technique, s.viewports[v].overrides));
    vps[v]->shownViews = s.viewports[v].views;
    shown.push_back(vps[v].get());
  }
  if (!shown.empty()) {
    Renderer renderer(shaders);
    renderer.setScene(scene);
    size_t row = 0;
    for (int f = 1; f <= s.frames.back(); ++f) {
      FrameInput in;
      in.camera = camera;
      in.width = l.panelW;
      in.height = l.panelH;
      in.cut = f == 1;
      renderer.render(in, shown);
      if (f == s.frames[row]) captureRow(out, l, fonts, s, panels, vps, static_cast<int>(row++), f);
    }
  } else {
    for (size_t row = 0; row < s.frames.size(); ++row)
      captureRow(out, l, fonts, s, panels, vps, static_cast<int>(row), s.frames[row]);
  }
  const int body = fonts.lineHeight(FigureFonts::Style::Body);
  int y = l.gridTop + l.rows * l.cellH;
  if (l.plotH > 0) {
    out.plot = stepPlot(tour, step, scene, camera, shaders, l.panelW, l.panelH);
    drawFigurePlot(out.image, fonts, out.plot, l.margin, y, l.plotW, l.plotH);
    y += l.plotH + l.margin;
  }
  for (const auto& line : l.captionLines) {
    fonts.draw(out.image, l.margin, y, line, FigureFonts::Style::Body, kText);
    y += body;
  }
  return out;
}

}  // namespace sl
