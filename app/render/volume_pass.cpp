// Renderer::addVolumesPass: participating media in the camera view. Only scenes with volumes
// get the pass ("simulate only the effects a scene calls for"); every technique's viewport runs
// it with its own prelude, so the medium is lit through that technique's visibility.
#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "scene/scene_effects.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace sl {

void Renderer::bindVolumes() {
  if (!volumes_) volumes_ = std::make_unique<VolumesBuffer>();
  volumes_->upload(*scene_);
  volumes_->bind();
}

void Renderer::addVolumesPass(FrameGraph& g, Viewport& vp, const std::string& tag, const std::string& prelude,
                              const Texture2D* depth, const std::vector<std::string>& reads) {
  if (!sceneEffects(*scene_).media) return;
  std::vector<std::string> inputs = reads;
  inputs.push_back("color" + tag);
  g.add({"volumes" + tag, inputs, {"color" + tag}, [this, &vp, prelude, depth] {
           const Technique& t = vp.technique;
           ProgramSpec spec{"volumes " + t.layout->id() + "+" + t.representation->id(),
                            {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/volumes.frag"}},
                            prelude};
           Program& p = shaders_.get(spec);
           if (!p.valid()) return;
           vp.colorFbo_.bind();
           p.use();
           TextureUnits units;
           bindTechnique(p, units, vp);
           bindVolumes();
           units.bind(p, "u_sceneDepth", depth->id());
           p.set("u_invViewProj", glm::inverse(proj_ * view_));
           p.set("u_cameraPosition", glm::vec3(glm::inverse(view_)[3]));
           glEnable(GL_BLEND);
           glBlendFunc(GL_ONE, GL_SRC_ALPHA);  // colour = medium + transmittance * surface
           drawFullscreen();
           glDisable(GL_BLEND);
         }});
}

}  // namespace sl
