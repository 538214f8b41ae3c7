// renderTourFigure (see figure.h): the step is rendered with the renderer `shadowlab render`
// uses, with a still camera, and each captured frame's images are copied into one CPU image.
#include "tour/figure.h"

#include "bench/reference_cache.h"
#include "explorer/explorer_state.h"
#include "gl/shader_library.h"
#include "part/colour_key.h"
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
  int plotW = 0, plotH = 0;       // the step's plot under the grid, full width (0: none)
  int cols = 0, gridRows = 0;     // the grid of cells: every panel of every captured frame
  std::vector<glm::ivec2> slots;  // grid column and row of cell i (capture row * panels + panel)
  int width = 0, height = 0;
  std::vector<std::string> captionLines;
  // Top-left corner of cell `i`.
  glm::ivec2 cell(int i) const {
    const glm::ivec2 g = slots[size_t(i)];
    return {margin + g.x * cellW, gridTop + g.y * cellH};
  }
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
    // With one viewport its name is the colour panel's title; the views are named alone, so that
    // the frame count after them is not cut off.
    const std::string prefix = s.viewports.size() == 1 ? "" : name + " \xC2\xB7 ";
    for (const auto& view : vp.views) panels.push_back({v, view, false, prefix + view});
  }
  return panels;
}

// The view's key when it is a gradient (a categorical key has no bar to draw under a panel).
const ColourKey* gradientKey(const std::string& view) {
  const ColourKey* key = viewColourKey(view);
  return key && !key->stops.empty() ? key : nullptr;
}

// Where each cell goes: in reading order, `cols` to a row.
std::vector<glm::ivec2> readingOrder(int cells, int cols) {
  std::vector<glm::ivec2> slots;
  for (int i = 0; i < cells; ++i) slots.push_back({i % cols, i / cols});
  return slots;
}

// Each viewport a column, its colour image on top and its views under it; captured frame counts
// side by side (framesAcross: a column per viewport and frame count) or stacked (a block of rows
// per frame count). A viewport's panels stay together either way.
std::vector<glm::ivec2> viewportColumns(const std::vector<Panel>& panels, int frames, bool framesAcross) {
  std::vector<glm::ivec2> slots;
  const int viewports = panels.empty() ? 0 : static_cast<int>(panels.back().viewport) + 1;
  int tallest = 0;
  for (size_t c = 0, below = 0; c < panels.size(); ++c) {
    below = c > 0 && panels[c].viewport == panels[c - 1].viewport ? below + 1 : 0;
    tallest = std::max(tallest, static_cast<int>(below) + 1);
  }
  for (int f = 0; f < frames; ++f) {
    int below = 0;
    for (size_t c = 0; c < panels.size(); ++c) {
      below = c > 0 && panels[c].viewport == panels[c - 1].viewport ? below + 1 : 0;
      const int column = static_cast<int>(panels[c].viewport);
      slots.push_back(framesAcross ? glm::ivec2(f * viewports + column, below)
                                   : glm::ivec2(column, f * tallest + below));
    }
  }
  return slots;
}

FigureLayout layOutGrid(const TourStep& s, const std::vector<Panel>& panels, const FigureFonts& fonts,
                        const FigureOptions& o, std::vector<glm::ivec2> slots) {
  FigureLayout l;
  l.panelW = o.panelWidth, l.panelH = o.panelHeight;
  l.slots = std::move(slots);
  for (const glm::ivec2& g : l.slots) l.cols = std::max(l.cols, g.x + 1), l.gridRows = std::max(l.gridRows, g.y + 1);
  const bool anyKey =
      std::any_of(panels.begin(), panels.end(), [](const Panel& p) { return !p.view.empty() && gradientKey(p.view); });
  const int body = fonts.lineHeight(FigureFonts::Style::Body);
  l.keyH = anyKey ? 4 + kKeyBar + body : 0;
  l.cellW = l.panelW + l.margin;
  l.cellH = body + l.panelH + l.keyH + l.margin;
  l.width = l.margin + l.cols * l.cellW;
  l.headerH = l.margin + fonts.lineHeight(FigureFonts::Style::Title);
  l.gridTop = l.headerH + l.margin / 2;
  if (s.plot.kind != TourPlot::Kind::None) {  // the full width, and at least 480 wide to be legible
    l.width = std::max(l.width, 480 + 2 * l.margin);
    l.plotW = l.width - 2 * l.margin;
    l.plotH = std::max(l.panelH, 200) + 4 * body;
  }
  l.captionLines = fonts.wrap(s.shownCaption(), l.width - 2 * l.margin, FigureFonts::Style::Body);
  l.height = l.gridTop + l.gridRows * l.cellH + (l.plotH > 0 ? l.plotH + l.margin : 0) +
             static_cast<int>(l.captionLines.size()) * body + l.margin;
  return l;
}

// The grid whose figure comes closest to the aspect asked for (16:9 by default): six panels of
// three viewports become three by two, not a strip. The structured grids (a row per frame count;
// viewports as columns, frame counts across or stacked) win unless plain reading order comes
// clearly closer to the aspect.
FigureLayout layOut(const TourStep& s, const std::vector<Panel>& panels, const FigureFonts& fonts,
                    const FigureOptions& o) {
  const int frames = static_cast<int>(s.frames.size());
  const int perFrame = std::max(static_cast<int>(panels.size()), 1);
  const int cells = perFrame * frames;
  auto miss = [&](const FigureLayout& l) {
    return std::abs(std::log(double(l.width) / double(l.height) / double(o.aspect)));
  };
  FigureLayout best;
  double bestMiss = 1e30;
  for (auto slots :
       {readingOrder(cells, perFrame), viewportColumns(panels, frames, true), viewportColumns(panels, frames, false)}) {
    FigureLayout l = layOutGrid(s, panels, fonts, o, std::move(slots));
    if (miss(l) < bestMiss - 1e-9) bestMiss = miss(l), best = std::move(l);
  }
  const double slack = std::log(1.5);  // how much closer reading order must come to replace them
  bestMiss -= slack;
  for (int cols = 1; cols <= cells; ++cols) {
    FigureLayout l = layOutGrid(s, panels, fonts, o, readingOrder(cells, cols));
    if (miss(l) < bestMiss - 1e-9) bestMiss = miss(l), best = std::move(l);
  }
  return best;
}

void drawColourKey(RgbaImage& img, const FigureFonts& fonts, const ColourKey& key, int x, int y, int w) {
  for (int i = 0; i < w; ++i)
    img.fillRect(x + i, y, 1, kKeyBar, sampleColourKey(key, w > 1 ? float(i) / float(w - 1) : 0.0f));
  // The labels' spans; the ends always, a middle one only where it overlaps none already kept.
  const int ty = y + kKeyBar + 2, gap = fonts.width(" ", FigureFonts::Style::Body);
  std::vector<glm::ivec2> spans(key.stops.size(), glm::ivec2(0));  // x, width (0: not drawn)
  for (size_t k = 0; k < key.stops.size(); ++k) {
    const ColourStop& stop = key.stops[k];
    if (stop.label.empty()) continue;
    const int tw = fonts.width(stop.label, FigureFonts::Style::Body);
    spans[k] = {std::clamp(x + static_cast<int>(stop.position * float(w)) - tw / 2, x, x + w - tw), tw};
  }
  auto overlaps = [&](size_t k, size_t j) {
    return spans[j].y > 0 && spans[k].x < spans[j].x + spans[j].y + gap && spans[j].x < spans[k].x + spans[k].y + gap;
  };
  std::vector<size_t> order;
  if (!spans.empty()) order = {0, spans.size() - 1};
  for (size_t k = 1; k + 1 < spans.size(); ++k) order.push_back(k);
  std::vector<size_t> kept;
  for (size_t k : order) {
    if (spans[k].y == 0 || std::find(kept.begin(), kept.end(), k) != kept.end()) continue;
    if (std::any_of(kept.begin(), kept.end(), [&](size_t j) { return overlaps(k, j); })) continue;
    kept.push_back(k);
    fonts.draw(img, spans[k].x, ty, key.stops[k].label, FigureFonts::Style::Body, kDimText);
  }
}

// `text` cut to `width` pixels with an ellipsis (a panel's title must not run into the next one).
std::string fitted(const FigureFonts& fonts, const std::string& text, int width) {
  if (fonts.width(text, FigureFonts::Style::Body) <= width) return text;
  std::string cut = text;
  while (!cut.empty() && fonts.width(cut + "\xE2\x80\xA6", FigureFonts::Style::Body) > width) {
    cut.pop_back();
    while (!cut.empty() && (static_cast<unsigned char>(cut.back()) & 0xC0) == 0x80) cut.pop_back();  // UTF-8
    if (!cut.empty() && static_cast<unsigned char>(cut.back()) >= 0xC0) cut.pop_back();
  }
  return cut + "\xE2\x80\xA6";
}

std::string frameSuffix(const TourStep& s, int frames) {
  if (s.frames.size() == 1 && frames == 1) return "";
  return " \xC2\xB7 " + std::to_string(frames) + (frames == 1 ? " frame" : " frames");
}

// Copies one capture (a row) of every panel from the viewports' textures.
void captureRow(FigureResult& out, const FigureLayout& l, const FigureFonts& fonts, const TourStep& s,
                const std::vector<Panel>& panels, const std::vector<std::unique_ptr<Viewport>>& vps, int row,
                int frames, const ReferenceImage* reference) {
  const int body = fonts.lineHeight(FigureFonts::Style::Body);
  for (size_t c = 0; c < panels.size(); ++c) {
    const Panel& p = panels[c];
    const glm::ivec2 at = l.cell(row * static_cast<int>(panels.size()) + static_cast<int>(c));
    const int x = at.x, y = at.y;
    // The name gives way to the frame count: cut the name, never the count after it.
    const std::string suffix = frameSuffix(s, frames);
    const std::string title = fitted(fonts, p.title, l.panelW - fonts.width(suffix, FigureFonts::Style::Body)) + suffix;
    fonts.draw(out.image, x, y, fitted(fonts, title, l.panelW), FigureFonts::Style::Body, kText);
    const int iy = y + body;
    if (p.placeholder) {
      out.image.fillRect(x, iy, l.panelW, l.panelH, {0.18f, 0.18f, 0.2f});
      fonts.draw(out.image, x + 8, iy + l.panelH / 2 - body / 2, "not built yet", FigureFonts::Style::Body, kDimText);
      continue;
    }
    const Viewport& vp = *vps[p.viewport];
    if (p.view == kErrorView) {
      out.image.blitBottomUp(viewportErrorImage(vp, *reference), l.panelW, l.panelH, x, iy);
    } else {
      const Texture2D* tex = p.view.empty() ? vp.colorTexture() : vp.viewTexture(p.view);
      if (!tex) throw std::runtime_error("view '" + p.view + "' was not drawn");
      out.image.blitBottomUp(tex->readRgba8(), l.panelW, l.panelH, x, iy);
    }
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

Scene stepSceneWithLight(const Tour& tour, size_t step, const std::string& assetsDir) {
  const TourStep& s = tour.steps.at(step);
  Scene scene = loadStepScene(tour, step, assetsDir.empty() ? defaultAssetsDir() : assetsDir);
  if (s.setLight) scene.light.direction = directionFromLightAngles(s.lightAngles.x, s.lightAngles.y);
  return scene;
}

FigureResult renderTourFigure(const Tour& tour, size_t step, ShaderLibrary& shaders, const FigureOptions& o) {
  const TourStep& s = tour.steps.at(step);
  const Scene scene = stepSceneWithLight(tour, step, o.assetsDir);
  const Camera camera = stepCamera(tour, step, scene);

  // Text at least 1/40 of the figure's height (legible on a slide): the layout depends on the
  // text size, so grow the text until it holds.
  float bodyPx = std::clamp(o.panelHeight / 16.0f, 11.0f, 20.0f);
  std::unique_ptr<FigureFonts> fonts;
  const std::vector<Panel> panels = panelsOf(s);
  FigureLayout l;
  for (int attempt = 0; attempt < 6; ++attempt) {
    fonts = std::make_unique<FigureFonts>(bodyPx, bodyPx * 1.4f);
    l = layOut(s, panels, *fonts, o);
    const float needed = float(l.height) / 40.0f;
    if (bodyPx >= needed) break;
    bodyPx = std::ceil(needed * 1.05f);
  }
  FigureResult out;
  out.bodyPixels = bodyPx;
  out.image = RgbaImage(l.width, l.height, kBackground);
  fonts->draw(out.image, l.margin, l.margin / 2, s.title, FigureFonts::Style::Title, kText);

  std::vector<std::unique_ptr<Viewport>> vps(s.viewports.size());
  std::vector<Viewport*> shown;
  for (size_t v = 0; v < s.viewports.size(); ++v) {
    if (!findPreset(s.viewports[v].technique)) continue;
    vps[v] = std::make_unique<Viewport>(makeTechnique(s.viewports[v].technique, s.viewports[v].overrides));
    for (const std::string& view : s.viewports[v].views)
      if (view != kErrorView) vps[v]->shownViews.push_back(view);
    shown.push_back(vps[v].get());
  }
  if (!shown.empty()) {
    Renderer renderer(shaders);
    renderer.setScene(scene);
    // The error view's truth: the scene traced once for the still camera.
    std::unique_ptr<ReferenceImage> reference;
    if (std::any_of(panels.begin(), panels.end(), [](const Panel& p) { return p.view == kErrorView; })) {
      FrameInput in;
      in.camera = camera;
      in.width = l.panelW;
      in.height = l.panelH;
      ReferenceCache cache(scene, ReferenceSettings{});
      reference = std::make_unique<ReferenceImage>(cache.forFrame(renderer, in));
    }
    size_t row = 0;
    for (int f = 1; f <= s.frames.back(); ++f) {
      FrameInput in;
      in.camera = camera;
      in.width = l.panelW;
      in.height = l.panelH;
      in.cut = f == 1;
      renderer.render(in, shown);
      if (f == s.frames[row]) captureRow(out, l, *fonts, s, panels, vps, static_cast<int>(row++), f, reference.get());
    }
  } else {
    for (size_t row = 0; row < s.frames.size(); ++row)
      captureRow(out, l, *fonts, s, panels, vps, static_cast<int>(row), s.frames[row], nullptr);
  }
  const int body = fonts->lineHeight(FigureFonts::Style::Body);
  int y = l.gridTop + l.gridRows * l.cellH;
  if (l.plotH > 0) {
    out.plot = stepPlot(tour, step, scene, camera, shaders, l.panelW, l.panelH);
    drawFigurePlot(out.image, *fonts, out.plot, l.margin, y, l.plotW, l.plotH);
    y += l.plotH + l.margin;
  }
  for (const auto& line : l.captionLines) {
    fonts->draw(out.image, l.margin, y, line, FigureFonts::Style::Body, kText);
    y += body;
  }
  return out;
}

}  // namespace sl
