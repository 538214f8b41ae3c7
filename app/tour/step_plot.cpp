// stepPlot (see step_plot.h).
#include "tour/step_plot.h"

#include "plot/dpds.h"
#include "plot/visibility_plot_data.h"

#include <algorithm>
#include <stdexcept>

namespace sl {
namespace {

// Overrides every viewport of the step shares (a filter width, say) hold for the plotted
// techniques too, so the plot shows what the panels show.
std::vector<std::string> sharedOverrides(const TourStep& s) {
  std::vector<std::string> shared;
  if (s.viewports.empty()) return shared;
  for (const auto& o : s.viewports.front().overrides)
    if (std::all_of(s.viewports.begin(), s.viewports.end(), [&](const TourViewport& v) {
          return std::find(v.overrides.begin(), v.overrides.end(), o) != v.overrides.end();
        }))
      shared.push_back(o);
  return shared;
}

}  // namespace

Plot stepPlot(const Tour& tour, size_t step, const Scene& scene, const Camera& camera, ShaderLibrary& shaders,
              int width, int height) {
  const TourStep& s = tour.steps.at(step);
  try {
    if (s.plot.kind == TourPlot::Kind::Dpds) {
      std::vector<std::string> specs = s.plot.techniques;
      for (std::string& spec : specs) std::replace(spec.begin(), spec.end(), ';', ',');  // one technique's overrides
      return dpdsPlot(dpdsCurves(scene, camera, width, height, specs), "dp/ds on '" + scene.name + "'");
    }
    if (s.plot.kind == TourPlot::Kind::Visibility) {
      const VisibilityPlotRequest request{.techniques = s.plot.techniques,
                                          .overrides = sharedOverrides(s),
                                          .width = width,
                                          .height = height,
                                          .pixel = s.plot.pixel};
      return visibilityPlot(shaders, scene, camera, request);
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(tour.file + ": " + describeStep(tour, step) + ".plot: " + e.what());
  }
  return {};
}

}  // namespace sl
