#include "part/uniforms.h"

#include "gl/shader_library.h"

#include <cmath>

namespace sl {

// Every parameter reaches the shaders as a float uniform named after its key, plus the map size
// and the light; modules declare only what they use. The light views are a uniform block.
void setTechniqueUniforms(const Program& p, const Technique& t, const LightSpace& ls, const Light& light) {
  for (const auto& d : t.params.decls()) p.set(uniformName(d.key), static_cast<float>(t.params.get(d.key)));
  p.set("u_shadowMapSize", static_cast<float>(ls.size));
  setLightUniforms(p, light);
}

void setLightUniforms(const Program& p, const Light& light) {
  p.set("u_lightDirection", glm::normalize(light.direction));
  p.set("u_lightPosition", light.position);
  p.set("u_spotCosHalfAngle", std::cos(glm::radians(light.fovDeg) * 0.5f));
  p.set("u_lightRadius", light.radius);
}

}  // namespace sl
