// stepPlot (see step_plot.h).
#include "tour/step_plot.h"

#include "plot/dpds.h"
#include "plot/visibility_plot_data.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sl {
namespace {

// The plot's pixel at a panel of width x height: "point" is a share of the panel, so that the
// plot shows the same place at any size; else "pixel" as given (-1: the centre).
glm::ivec2 stepPlotPixel(const TourPlot& p, int width, int height) {
  if (p.point.x < 0.0f) return p.pixel;
  return {static_cast<int>(std::lround(p.point.x * float(width - 1))),
          static_cast<int>(std::lround(p.point.y * float(height - 1)))};
}

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

std::string stepSeriesLabel(const TourStep& s, const std::string& spec) {
  const size_t colon = spec.find(':');
  const std::string preset = spec.substr(0, colon);
  std::vector<std::string> sets;
  for (size_t at = colon; at != std::string::npos && at + 1 < spec.size();) {
    const size_t next = spec.find_first_of(";,", at + 1);
    sets.push_back(spec.substr(at + 1, next == std::string::npos ? std::string::npos : next - at - 1));
    at = next;
  }
  std::vector<std::string> sortedSets = sets;
  std::sort(sortedSets.begin(), sortedSets.end());
  for (const TourViewport& v : s.viewports) {
    std::vector<std::string> o = v.overrides;
    std::sort(o.begin(), o.end());
    if (v.technique == preset && o == sortedSets && !v.label.empty()) return v.label;
  }
  std::string label = preset;
  for (size_t k = 0; k < sets.size(); ++k) label += (k == 0 ? " (" : ", ") + sets[k];
  return sets.empty() ? label : label + ")";
}

Plot stepPlot(const Tour& tour, size_t step, const Scene& scene, const Camera& camera, ShaderLibrary& shaders,
              int width, int height) {
  const TourStep& s = tour.steps.at(step);

  try {
    if (s.plot.kind == TourPlot::Kind::Dpds) {
      std::vector<std::string> specs = s.plot.techniques;
      for (std::string& spec : specs) std::replace(spec.begin(), spec.end(), ';', ',');  // one technique's overrides
      Plot plot = dpdsPlot(dpdsCurves(scene, camera, width, height, specs), "dp/ds on '" + scene.name + "'");
      for (size_t k = 0; k < s.plot.techniques.size() && k < plot.series.size(); ++k)
        plot.series[k].label = stepSeriesLabel(s, s.plot.techniques[k]);
      return plot;
    }
    if (s.plot.kind == TourPlot::Kind::Visibility) {
      const VisibilityPlotRequest request{.techniques = s.plot.techniques,
                                          .overrides = sharedOverrides(s),
                                          .width = width,
                                          .height = height,
                                          .pixel = stepPlotPixel(s.plot, width, height)};
      return visibilityPlot(shaders, scene, camera, request);
    }
  } catch (const std::exception& e) {
    throw std::runtime_error(tour.file + ": " + describeStep(tour, step) + ".plot: " + e.what());
  }
  return {};
}

}  // namespace sl
