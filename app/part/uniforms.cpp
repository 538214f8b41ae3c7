#include "part/uniforms.h"

#include "gl/shader_library.h"

#include <cmath>

namespace sl {

// Every parameter reaches the shaders as a float uniform named after its key, plus the map size
// and the light; modules declare only what they use. The light views are a uniform block.
void setTechniqueUniforms(const Program& p, const Technique& t, const LightSpace& ls, const Light& light) {
  setTechniqueUniforms(p, t.params, ls, light);
}

void setTechniqueUniforms(const Program& p, const ParamSet& params, const LightSpace& ls, const Light& light) {
  for (const auto& d : params.decls()) p.set(uniformName(d.key), static_cast<float>(params.get(d.key)));
  p.set("u_shadowMapSize", static_cast<float>(ls.size));
  setLightUniforms(p, light);
}

void setLightUniforms(const Program& p, const Light& light) {
  p.set("u_lightDirection", glm::normalize(light.direction));
  p.set("u_lightPosition", light.position);
  // A point light has no cone: every direction passes the test (common/light.glsl).
  p.set("u_spotCosHalfAngle", light.type == Light::Type::Point ? -2.0f : std::cos(glm::radians(light.fovDeg) * 0.5f));
  p.set("u_lightRadius", light.radius);
  p.set("u_lightRange", light.range > 0.0f ? light.range : 1e30f);
  p.set("u_lightColor", light.color);
}

std::string lightDefines(const Light& light) {
  std::string d;
  if (light.positional()) d += "#define SL_SPOT_LIGHT\n";  // the light sits at u_lightPosition
  if (light.type == Light::Type::Point) d += "#define SL_POINT_LIGHT\n";
  return d;
}

}  // namespace sl
