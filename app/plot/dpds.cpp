#include "plot/dpds.h"

#include "part/light_frame.h"
#include "part/light_space.h"
#include "technique.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace sl {

namespace {

Technique parseTechnique(const std::string& spec) {
  const auto colon = spec.find(':');
  std::vector<std::string> sets;
  if (colon != std::string::npos) {
    std::stringstream rest(spec.substr(colon + 1));
    for (std::string kv; std::getline(rest, kv, ',');) sets.push_back(kv);
  }
  return makeTechnique(spec.substr(0, colon), sets);
}

// The view a layout's shader would pick for a point at camera depth z (partitioned layouts by
// split, the others their one view), and whether the point is in that view's map.
const LightView* viewFor(const LightSpace& ls, float z) {
  for (const LightView& v : ls.views)
    if (z < v.splitFar) return &v;
  return &ls.views.back();
}

glm::vec2 texelsAt(const LightView& v, int size, const glm::vec3& p, bool& inside) {
  const glm::vec4 c = lightViewClip(v, p);  // the log warp (LogPSM) included
  inside = c.w > 1e-6f && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w;
  return glm::vec2(c) / c.w * (0.5f * static_cast<float>(size));
}

}  // namespace

std::vector<DpdsCurve> dpdsCurves(const Scene& scene, const Camera& cam, int width, int height,
                                  const std::vector<std::string>& techniques, int samples) {
  std::vector<Technique> made;
  for (const std::string& spec : techniques) made.push_back(parseTechnique(spec));
  std::vector<LabelledTechnique> labelled;
  for (size_t i = 0; i < made.size(); ++i) labelled.push_back({techniques[i], &made[i]});
  return dpdsCurves(scene, cam, width, height, labelled, samples);
}

std::vector<DpdsCurve> dpdsCurves(const Scene& scene, const Camera& cam, int width, int height,
                                  const std::vector<LabelledTechnique>& techniques, int samples) {
  const glm::mat4 view = cameraView(cam), proj = cameraProjection(cam, float(width) / float(height));
  const glm::vec3 eye = cam.position, dir = glm::normalize(cam.target - cam.position);
  const glm::vec3 L = glm::normalize(scene.light.direction);
  glm::vec3 across = dir - L * glm::dot(dir, L);  // the view direction as the light sees it
  across = glm::length(across) > 1e-4f ? glm::normalize(across) : glm::normalize(glm::cross(L, glm::vec3(0, 1, 0)));
  float zFar = cam.nearPlane * 2.0f;
  for (const auto& p : clipFrustumToBox(view, proj, scene.boundsAt(0))) zFar = std::max(zFar, glm::dot(p - eye, dir));
  zFar = std::min(zFar, cam.farPlane);
  const float pixelPerDepth = 2.0f * std::tan(glm::radians(cam.fovDeg) * 0.5f) / static_cast<float>(height);
  std::vector<DpdsCurve> out;
  int firstSize = 0;
  for (const LabelledTechnique& lt : techniques) {
    const Technique& t = *lt.technique;
    LayoutInput in;
    in.scene = &scene;
    in.cameraView = view;
    in.cameraProj = proj;
    in.params = &t.params;
    const LightSpace ls = t.layout->compute(in);
    if (firstSize == 0) firstSize = ls.size;
    DpdsCurve c;
    c.label = lt.label;
    for (int i = 0; i < samples; ++i) {
      const float z = cam.nearPlane * std::pow(zFar / cam.nearPlane, (i + 0.5f) / samples);
      const glm::vec3 p = eye + dir * z;
      const float step = 1e-3f * z;
      const LightView* v = viewFor(ls, z);
      bool in0 = false, in1 = false;
      const float texels = glm::length(texelsAt(*v, ls.size, p + across * step, in1) - texelsAt(*v, ls.size, p, in0));
      c.depth.push_back(z);
      c.ratio.push_back(in0 && in1 && texels > 0.0f ? (step / texels) / (pixelPerDepth * z)
                                                    : std::numeric_limits<float>::quiet_NaN());
    }
    out.push_back(std::move(c));
  }
  // Logarithmic parametrization with the first technique's texels per side: a texel covers
  // z ln(f/n) / N at depth z, a constant multiple of the pixel size.
  DpdsCurve ideal;
  ideal.label = "ideal logarithmic";
  for (int i = 0; i < samples && firstSize > 0; ++i) {
    const float z = cam.nearPlane * std::pow(zFar / cam.nearPlane, (i + 0.5f) / samples);
    ideal.depth.push_back(z);
    ideal.ratio.push_back(std::log(zFar / cam.nearPlane) / firstSize / pixelPerDepth);
  }
  out.push_back(std::move(ideal));
  return out;
}

Plot dpdsPlot(const std::vector<DpdsCurve>& curves, const std::string& title) {
  Plot plot;
  plot.title = title;
  plot.x = {.label = "view depth z (log)", .log = true};
  plot.y = {.label = "shadow-map texel / pixel size along the view (log; 1 = one texel per pixel)", .log = true};
  for (size_t k = 0; k < curves.size(); ++k) {
    PlotSeries s{.label = curves[k].label, .colour = plotColour(k), .width = 2.0f};
    for (size_t i = 0; i < curves[k].depth.size(); ++i) s.points.emplace_back(curves[k].depth[i], curves[k].ratio[i]);
    plot.series.push_back(std::move(s));
  }
  if (!plot.series.empty()) plot.series.back().colour = glm::vec3(0.4f);  // the ideal curve: grey
  return plot;
}

}  // namespace sl
