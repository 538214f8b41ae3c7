// visibilityPlot (see visibility_plot_data.h): each technique renders one frame with its own
// renderer state; the first one's G-buffer finds the surface under the pixel.
#include "plot/visibility_plot_data.h"

#include "gl/shader_library.h"
#include "part/light_frame.h"
#include "render/renderer.h"
#include "technique.h"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace sl {

Plot visibilityPlot(ShaderLibrary& shaders, const Scene& scene, const Camera& camera, const VisibilityPlotRequest& r) {
  const int px = std::clamp(r.pixel.x < 0 ? r.width / 2 : r.pixel.x, 0, r.width - 1);
  const int py = std::clamp(r.pixel.y < 0 ? r.height / 2 : r.pixel.y, 0, r.height - 1);
  const std::string where = "pixel " + std::to_string(px) + "," + std::to_string(py);
  Renderer renderer(shaders);
  renderer.setScene(scene);
  Plot plot;
  plot.x = {.label = "receiver depth (light space, " + std::to_string(r.lo).substr(0, 4) + " to " +
                     std::to_string(r.hi).substr(0, 4) + ")",
            .lo = r.lo,
            .hi = r.hi};
  plot.y = {.label = "visibility", .lo = -0.2f, .hi = 1.2f, .ticks = {0.0f, 0.5f, 1.0f}};
  glm::vec3 uvLayer(0.5f, 0.5f, 0.0f);
  float receiver = 0.5f;
  // Values beyond the y range are drawn on its border; depths outside [lo, hi] are left out.
  auto series = [&](std::string label, glm::vec3 colour, float width, const std::vector<float>& values) {
    PlotSeries s = evenlySpacedSeries(std::move(label), colour, width, values);
    std::erase_if(s.points, [&](glm::vec2 p) { return p.x < r.lo || p.x > r.hi; });
    plot.series.push_back(std::move(s));
  };
  for (const std::string& id : r.techniques) {
    Viewport vp(makeTechnique(id, r.overrides));
    FrameInput in;
    in.camera = camera;
    in.width = r.width;
    in.height = r.height;
    renderer.render(in, {&vp});
    CurveQuery q{
        .shaders = &shaders, .technique = &vp.technique, .view = &vp.lightSpace.primary(), .samples = r.samples};
    if (plot.series.empty()) {
      const std::vector<float> pos = renderer.gPosition().readFloats(4);
      const size_t i = (static_cast<size_t>(py) * size_t(r.width) + size_t(px)) * 4;
      if (pos[i + 3] < 0.5f) throw std::runtime_error(where + " shows no surface");
      if (!mapPointOf(glm::vec3(pos[i], pos[i + 1], pos[i + 2]), vp.lightSpace.primary(), uvLayer, receiver))
        throw std::runtime_error(where + " is behind the light's view");
    }
    q.uvLayer = uvLayer;
    const VisibilityCurve c = vp.representation->visibilityCurve(q);
    if (c.axis != "receiver depth" || c.truth.empty())
      throw std::runtime_error("technique '" + id +
                               "' is not pre-filtered (its representation has no visibility curve against receiver "
                               "depth)");
    if (plot.series.empty()) series(c.truthLabel, glm::vec3(0.0f), 2.5f, c.truth);
    series(id, plotColour(plot.series.size() - 1), 1.5f, c.values);
  }
  std::ostringstream title;
  title << scene.name << ", " << where << ": visibility vs receiver depth at map uv " << uvLayer.x << ", " << uvLayer.y;
  plot.title = title.str();
  plot.markers = {receiver};
  plot.note = "dashed: this pixel's receiver depth " + std::to_string(receiver).substr(0, 5);
  return plot;
}

}  // namespace sl
