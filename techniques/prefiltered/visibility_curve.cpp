#include "prefiltered/visibility_curve.h"

#include "gl/gl_util.h"
#include "gl/texture_units.h"
#include "part/uniforms.h"

#include <cmath>

namespace sl {

VisibilityCurve MomentMapState::visibilityCurve(const CurveQuery& q) const {
  VisibilityCurve c{.axis = "receiver depth", .valueLabel = "visibility"};
  const int width = q.technique->params.i("filter.width");
  c.values = reconstructedCurve(*q.shaders, *q.technique, *this, q.uvLayer, q.samples);
  c.truthLabel = "true (box of " + std::to_string(width) + " texels)";
  c.truth = trueCurve(depth_, q.uvLayer, width, q.samples);
  return c;
}

std::vector<float> reconstructedCurve(ShaderLibrary& shaders, const Technique& t, const MomentMapState& state,
                                      const glm::vec3& uvLayer, int samples) {
  const std::string prelude = state.defines() + "#include \"" + t.representation->glslModule() + "\"\n";
  Program& p =
      shaders.get({"visibility curve",
                   {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "views/visibility_curve.frag"}},
                   prelude});
  if (!p.valid()) return {};
  Texture2D target(GL_RGBA32F, samples, 1, "visibility curve");
  Framebuffer fbo("visibility curve");
  fbo.attach({&target}, nullptr);
  fbo.bind();
  p.use();
  setTechniqueUniforms(p, t, LightSpace{}, Light{});
  p.set("u_uvLayer", uvLayer);
  p.set("u_samples", static_cast<float>(samples));
  {
    TextureUnits units;
    state.bind(p, units);
    drawFullscreenTriangle();
  }
  std::vector<float> rgba = target.readFloats(4), out;
  for (size_t i = 0; i < rgba.size(); i += 4) out.push_back(rgba[i]);
  return out;
}

std::vector<float> trueCurve(const Texture2D& depth, const glm::vec3& uvLayer, int width, int samples) {
  const int n = depth.width();
  const int cx = static_cast<int>(std::floor(uvLayer.x * n)), cy = static_cast<int>(std::floor(uvLayer.y * n));
  // The box clamped to the map, as the clamp-to-edge filters see it (edge texels repeat).
  const int x0 = std::clamp(cx - width / 2, 0, n - 1), x1 = std::clamp(cx + width / 2, 0, n - 1);
  const int y0 = std::clamp(cy - width / 2, 0, n - 1), y1 = std::clamp(cy + width / 2, 0, n - 1);
  const int bw = x1 - x0 + 1, bh = y1 - y0 + 1;
  std::vector<float> region(static_cast<size_t>(bw) * bh);
  glGetTextureSubImage(depth.id(), 0, x0, y0, static_cast<int>(uvLayer.z), bw, bh, 1, GL_DEPTH_COMPONENT, GL_FLOAT,
                       static_cast<GLsizei>(region.size() * sizeof(float)), region.data());
  std::vector<float> box;
  for (int y = cy - width / 2; y <= cy + width / 2; ++y)
    for (int x = cx - width / 2; x <= cx + width / 2; ++x)
      box.push_back(region[static_cast<size_t>(std::clamp(y, y0, y1) - y0) * bw + (std::clamp(x, x0, x1) - x0)]);
  std::vector<float> out;
  for (int s = 0; s < samples; ++s) {
    const float d = static_cast<float>(s) / static_cast<float>(std::max(samples - 1, 1));
    int lit = 0;
    for (float z : box) lit += d <= z ? 1 : 0;
    out.push_back(static_cast<float>(lit) / static_cast<float>(box.size()));
  }
  return out;
}

}  // namespace sl
