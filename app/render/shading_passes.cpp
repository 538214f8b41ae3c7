// The passes that turn a viewport's shadow test into its colour, which an accumulation adds
// through its context (AccumulationContext::addForwardShade, addVisibilityTest,
// addDeferredShade): forward (test and shading while the scene is rasterized), the fullscreen
// visibility test over the G-buffer, and the deferred shade pass that reads a visibility texture.
#include "render/gpu_scene.h"
#include "render/renderer.h"

namespace sl {

AccumulationOutput Renderer::addForwardShadePass(FrameGraph& g, Viewport& vp, const std::string& tag,
                                                 const std::string& prelude, const std::string& shadowMap,
                                                 const ProgramSetup& bindInputs, const FrameInput& in) {
  g.add({"shade" + tag, {shadowMap}, {"color" + tag, "visibility.raw" + tag}, [this, &vp, prelude, bindInputs, &in] {
           const Technique& t = vp.technique;
           ProgramSpec spec{"forward " + t.layout->id() + "+" + t.representation->id(),
                            {{GL_VERTEX_SHADER, "passes/gbuffer.vert"}, {GL_FRAGMENT_SHADER, "passes/forward.frag"}},
                            prelude};
           vp.forwardFbo_.bind();
           const float background[4] = {1.0f, 0.0f, 0.0f, 0.0f};  // visibility 1, confidence 0
           glClearNamedFramebufferfv(vp.forwardFbo_.id(), GL_COLOR, 1, background);
           glClearNamedFramebufferfi(vp.forwardFbo_.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
           drawSceneForward(spec, bindInputs, in.time, vp.prev_);
           drawSky();
         }});
  return {"visibility.raw" + tag, vp.rawVisibility_.get(), "color" + tag, vp.depth_.get()};
}

void Renderer::addVisibilityPass(FrameGraph& g, Viewport& vp, const std::string& tag, const std::string& prelude,
                                 const std::string& shadowMap, const ProgramSetup& bindInputs) {
  g.add({"visibility" + tag, {"gbuffer", shadowMap}, {"visibility.raw" + tag}, [this, &vp, prelude, bindInputs] {
           const Technique& t = vp.technique;
           ProgramSpec spec{
               "visibility " + t.layout->id() + "+" + t.representation->id(),
               {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/visibility.frag"}},
               prelude};
           Program& p = shaders_.get(spec);
           if (!p.valid()) return;
           vp.visibilityFbo_.bind();
           p.use();
           TextureUnits units;
           bindInputs(p, units);
           // An other light of limited reach: beyond its range every point is unlit with full
           // confidence (what the test would write there), so only its pixels run the test.
           const glm::ivec4 rect = vp.scissor_;
           if (rect.z > 0) {
             const float beyondRange[4] = {0.0f, 1.0f, 0.0f, 0.0f};
             glClearNamedFramebufferfv(vp.visibilityFbo_.id(), GL_COLOR, 0, beyondRange);
             glEnable(GL_SCISSOR_TEST);
             glScissor(rect.x, rect.y, rect.z, rect.w);
           }
           drawFullscreen();
           glDisable(GL_SCISSOR_TEST);
         }});
}

AccumulationOutput Renderer::addDeferredShadePass(FrameGraph& g, Viewport& vp, const std::string& tag,
                                                  const std::string& visibility, const Texture2D* visTex) {
  g.add({"shade" + tag, {"gbuffer", visibility}, {"color" + tag}, [this, &vp, visTex] {
           ProgramSpec spec{"shade",
                            {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/shade.frag"}},
                            lightDefines(lightOf(vp))};
           Program& p = shaders_.get(spec);
           if (!p.valid()) return;
           vp.colorFbo_.bind();
           p.use();
           TextureUnits units;
           setTechniqueUniforms(p, vp.frameParams_, vp.lightSpace, lightOf(vp));
           bindGBuffer(p, units, visTex);
           drawFullscreen();
         }});
  return {visibility, visTex, "gbuffer", gDepth_.get()};
}

}  // namespace sl
