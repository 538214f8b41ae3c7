#include "layouts/dpds.h"

#include "layouts/light_frame.h"

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
  const glm::vec4 c = v.viewProj * glm::vec4(p, 1.0f);
  inside = c.w > 1e-6f && std::abs(c.x) <= c.w && std::abs(c.y) <= c.w;
  return glm::vec2(c) / c.w * (0.5f * static_cast<float>(size));
}

}  // namespace

std::vector<DpdsCurve> dpdsCurves(const Scene& scene, const Camera& cam, int width, int height,
                                  const std::vector<std::string>& techniques, int samples) {
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
  for (const std::string& spec : techniques) {
    Technique t = parseTechnique(spec);
    LayoutInput in;
    in.scene = &scene;
    in.cameraView = view;
    in.cameraProj = proj;
    in.params = &t.params;
    const LightSpace ls = t.layout->compute(in);
    if (firstSize == 0) firstSize = ls.size;
    DpdsCurve c;
    c.label = spec;
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

std::string dpdsSvg(const std::vector<DpdsCurve>& curves, const std::string& title) {
  const float W = 720, H = 420, left = 70, right = 220, top = 40, bottom = 50;
  float zLo = 1e30f, zHi = -1e30f, rLo = 1e30f, rHi = -1e30f;
  for (const auto& c : curves)
    for (size_t i = 0; i < c.depth.size(); ++i) {
      if (!std::isfinite(c.ratio[i]) || c.ratio[i] <= 0.0f) continue;
      zLo = std::min(zLo, c.depth[i]);
      zHi = std::max(zHi, c.depth[i]);
      rLo = std::min(rLo, c.ratio[i]);
      rHi = std::max(rHi, c.ratio[i]);
    }
  if (zLo >= zHi) zHi = zLo * 10.0f + 1.0f;
  const float d0 = std::floor(std::log10(std::max(rLo, 1e-6f))),
              d1 = std::ceil(std::log10(std::max(rHi, 1e-6f))) + (rLo >= rHi);
  auto X = [&](float z) {
    return left + (W - left - right) * (std::log10(z) - std::log10(zLo)) / (std::log10(zHi) - std::log10(zLo));
  };
  auto Y = [&](float r) { return H - bottom - (H - top - bottom) * (std::log10(r) - d0) / std::max(d1 - d0, 1.0f); };
  static const char* colours[] = {"#d9412b", "#e8a317", "#3a9d3a", "#3b7dd8", "#8a5cc7", "#2bb0b0", "#666666"};
  std::ostringstream s;
  s << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H
    << "\" font-family=\"sans-serif\" font-size=\"12\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<text x=\"" << left << "\" y=\"22\" font-size=\"14\">"
    << title << "</text>\n";
  for (float d = d0; d <= d1; d += 1.0f)  // decades of texel/pixel size
    s << "<line x1=\"" << left << "\" x2=\"" << W - right << "\" y1=\"" << Y(std::pow(10.0f, d)) << "\" y2=\""
      << Y(std::pow(10.0f, d)) << "\" stroke=\"#ddd\"/><text x=\"8\" y=\"" << Y(std::pow(10.0f, d)) + 4 << "\">1e"
      << int(d) << "</text>\n";
  s << "<text x=\"" << left << "\" y=\"" << H - 15 << "\">view depth z (log, " << zLo << " to " << zHi
    << ") ; y: shadow-map texel / pixel size along the view direction (log; 1 = one texel per pixel)</text>\n";
  for (size_t k = 0; k < curves.size(); ++k) {
    const char* colour = colours[std::min(k, sizeof(colours) / sizeof(*colours) - 1)];
    s << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"2\" points=\"";
    for (size_t i = 0; i < curves[k].depth.size(); ++i)
      if (std::isfinite(curves[k].ratio[i]) && curves[k].ratio[i] > 0.0f)
        s << X(curves[k].depth[i]) << "," << Y(curves[k].ratio[i]) << " ";
    s << "\"/>\n<text x=\"" << W - right + 10 << "\" y=\"" << top + 18 * (k + 1) << "\" fill=\"" << colour << "\">"
      << curves[k].label << "</text>\n";
  }
  s << "</svg>\n";
  return s.str();
}

}  // namespace sl
