#include "tour/tour_claims.h"

#include "bench/reference_cache.h"
#include "tour/figure.h"
#include "metrics/metrics.h"
#include "render/renderer.h"
#include "technique.h"

#include <algorithm>
#include <cstdio>
#include <memory>

namespace sl {

namespace {

std::string percent(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f %%", v);
  return buf;
}

std::string describe(const TourStep& s, int viewport) {
  const TourViewport& v = s.viewports.at(static_cast<size_t>(viewport - 1));
  return "viewport " + std::to_string(viewport) + " (" + (v.label.empty() ? v.technique : v.label) + ")";
}

// A viewport's measurements at one captured frame.
struct Counts {
  ErrorMetrics visibility;
  double imageWrongPct = 0;
};

double counted(const Counts& c, TourClaim::Metric metric) {
  const ErrorMetrics& m = c.visibility;
  switch (metric) {
    case TourClaim::Metric::ImageWrong:
      return c.imageWrongPct;
    case TourClaim::Metric::FalseLight:
      return m.falseLightPct;
    case TourClaim::Metric::FalseShadow:
      return m.falseShadowPct;
    default:
      return m.wrongPixelPct;
  }
}

const char* metricName(TourClaim::Metric metric) {
  return metric == TourClaim::Metric::FalseLight    ? "falsely lit"
         : metric == TourClaim::Metric::FalseShadow ? "falsely shadowed"
         : metric == TourClaim::Metric::ImageWrong  ? "of the colour wrong"
                                                    : "wrong";
}

ClaimCheck judge(const TourStep& s, const TourClaim& c, const std::vector<std::vector<Counts>>& metrics) {
  ClaimCheck out;
  out.claim = c;
  const std::vector<Counts>& mine = metrics.at(static_cast<size_t>(c.viewport - 1));
  out.wrongPct = counted(mine.back(), c.metric);
  const bool better = c.kind == TourClaim::Kind::Better;
  out.comparedPct = counted(better ? metrics.at(static_cast<size_t>(c.than - 1)).back() : mine.front(), c.metric);
  out.holds = out.wrongPct * c.factor <= out.comparedPct;
  char factor[32];
  std::snprintf(factor, sizeof factor, "%g", c.factor);
  out.text = describe(s, c.viewport) + " " + percent(out.wrongPct) + " " + metricName(c.metric) +
             (better ? " at frame " + std::to_string(s.frames.back()) + ", " + describe(s, c.than) + " " +
                           percent(out.comparedPct)
                     : " at frame " + std::to_string(s.frames.back()) + ", " + percent(out.comparedPct) + " at frame " +
                           std::to_string(s.frames.front())) +
             ": claimed " + factor + "x fewer, " + (out.holds ? "holds" : "does NOT hold");
  return out;
}

}  // namespace

std::vector<ClaimCheck> checkStepClaims(const Tour& tour, size_t step, ShaderLibrary& shaders, int width, int height,
                                        const std::string& assetsDir) {
  const TourStep& s = tour.steps.at(step);
  if (s.claims.empty() || !s.built()) return {};
  const Scene scene = stepSceneWithLight(tour, step, assetsDir);
  FrameInput in;
  in.camera = stepCamera(tour, step, scene);
  in.width = width;
  in.height = height;
  Renderer renderer(shaders);
  renderer.setScene(scene);
  ReferenceCache cache(scene, ReferenceSettings{});
  const ReferenceImage ref = cache.forFrame(renderer, in);  // still camera: one reference for every frame
  std::vector<std::unique_ptr<Viewport>> vps;
  std::vector<Viewport*> shown;
  for (const TourViewport& v : s.viewports) {
    vps.push_back(std::make_unique<Viewport>(makeTechnique(v.technique, v.overrides)));
    shown.push_back(vps.back().get());
  }
  std::vector<std::vector<Counts>> metrics(vps.size());  // per viewport, per captured frame
  const bool image = std::any_of(s.claims.begin(), s.claims.end(),
                                 [](const TourClaim& c) { return c.metric == TourClaim::Metric::ImageWrong; });
  size_t row = 0;
  for (int f = 1; f <= s.frames.back(); ++f) {
    in.cut = f == 1;
    renderer.render(in, shown);
    if (f != s.frames[row]) continue;
    ++row;
    for (size_t v = 0; v < vps.size(); ++v) {
      const std::vector<float> vis = viewportVisibility(*vps[v]);
      Counts counts{compareVisibility(vis.data(), ref.visibility.data(), ref.valid.data(), vis.size()), 0};
      if (image)
        counts.imageWrongPct =
            viewportImageError(renderer, in, *vps[v], ref.visibility, ref.valid, ref.otherLights).imageWrongPct;
      metrics[v].push_back(counts);
    }
  }
  std::vector<ClaimCheck> out;
  for (const TourClaim& c : s.claims) out.push_back(judge(s, c, metrics));
  return out;
}

}  // namespace sl
