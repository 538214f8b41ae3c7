// How the renderer hands a viewport's frame to the technique's parts: what a part sees while it
// adds its passes (PartContext), what an accumulation sees (AccumulationContext), and the shadow
// pass that draws the light views into the representation's layers.
#include "render/gpu_scene.h"
#include "render/renderer.h"

namespace sl {

// Layout passes, then the shadow pass (one draw per light view into the representation's
// layers), then the representation's passes; the renderer only orders what the parts declare.
void Renderer::addShadowPass(FrameGraph& g, Viewport& vp, const std::string& tag, const std::vector<std::string>& reads,
                             const FrameInput& in) {
  const std::string prelude = techniquePrelude(vp);
  g.add({"shadowmap" + tag, reads, {"shadowmap" + tag}, [this, &vp, prelude, &in] {
           const Technique& t = vp.technique;
           glEnable(GL_DEPTH_TEST);
           static const GLenum culled[] = {GL_BACK, GL_FRONT, 0};  // front faces, back faces, both
           const ProgramSpec spec{"shadowmap " + t.layout->id() + "+" + t.representation->id(),
                                  casterStages(*t.layout, t.representation->shadowMapFragment()), prelude};
           const GLenum cull = culled[t.params.i("shadowmap.cull")];
           // A deep map draws its semi-transparent casters into its own fragment lists instead.
           const auto only = t.representation->opaqueShadowPass() ? GpuScene::Only::Opaque : GpuScene::Only::All;
           for (int layer = 0; layer < static_cast<int>(vp.lightSpace.views.size()); ++layer) {
             const glm::mat4* cullTo =
                 t.params.b("shadowmap.cull_instances") ? &vp.lightSpace.views[size_t(layer)].viewProj : nullptr;
             if (!vp.layout->drawsTiles()) {
               vp.representation->beginShadowLayer(layer);
               PassPrograms programs(shaders_, spec, [this, &vp, layer](const Program& p, TextureUnits& units) {
                 bindTechnique(p, units, vp);
                 p.set("u_shadowView", layer);
               });
               gpu_->draw(programs, in.time, in.time, cull, only, cullTo);
               continue;
             }
             // Piecewise (paged) layer: only the tiles the layout asks for, each into its viewport.
             const bool kept = vp.representation->bindShadowLayer(layer);
             const int tiles = vp.layout->shadowTiles(layer, kept);
             for (int tile = 0; tile < tiles; ++tile) {
               vp.layout->beginShadowTile(layer, tile);
               PassPrograms programs(shaders_, spec, [this, &vp, layer, tile](const Program& p, TextureUnits& units) {
                 bindTechnique(p, units, vp);
                 p.set("u_shadowView", layer);
                 vp.layout->bindShadowTile(p, layer, tile);
               });
               const glm::mat4 tileClip = cullTo ? vp.layout->shadowTileClip(layer, tile, *cullTo) : glm::mat4(1.0f);
               gpu_->draw(programs, in.time, in.time, cull, only, cullTo ? &tileClip : nullptr);
             }
             glDisable(GL_SCISSOR_TEST);
           }
           glDisable(GL_DEPTH_TEST);
         }});
}

// What every part of a viewport's technique sees while it adds its passes.
PartContext Renderer::partContext(Viewport& vp, const std::string& tag, const FrameInput& in, bool cameraMoved,
                                  const std::string& prelude) {
  PartContext part;
  part.viewportTag = tag;
  part.scene = scene_;
  part.time = in.time;
  part.shaders = &shaders_;
  part.params = &vp.technique.params;
  part.layout = vp.technique.layout;
  part.lightSpace = &vp.lightSpace;
  part.view = view_;
  part.proj = proj_;
  part.width = in.width;
  part.height = in.height;
  part.cameraMoved = cameraMoved;
  part.frameIndex = vp.frameIndex_;
  part.shadowMap = "shadowmap" + tag;
  // Last frame's, when there is one from the same view (not after a cut or a resize).
  part.previousVisibility = vp.visibilityHeld_ && !in.cut ? vp.visibilityTexture() : nullptr;
  part.viewTargets = vp.shownViewTargets();
  part.shadowDepth = [&vp]() -> const Texture2D* {
    return vp.representation ? vp.representation->depthTexture() : nullptr;
  };
  part.drawFullscreen = [this] { drawFullscreen(); };
  part.techniquePrelude = prelude;
  part.bindTechnique = [this, &vp](const Program& p, TextureUnits& units) { bindTechnique(p, units, vp); };
  part.bindGBuffer = [this](const Program& p, TextureUnits& units) { bindGBuffer(p, units); };
  part.drawSemiTransparent = [this, &in](const ProgramSpec& spec, const ProgramSetup& setup) {
    PassPrograms programs(shaders_, spec, setup);
    gpu_->draw(programs, in.time, in.time, 0, GpuScene::Only::SemiTransparent);
  };
  part.bindVolumes = [this] { bindVolumes(); };
  part.replaceLightSpace = [&vp](const LightSpace& ls) {
    vp.lightSpace = ls;
    vp.lightViews_->upload(vp.lightSpace);
  };
  return part;
}

// What an accumulation reads and writes for this viewport's frame.
AccumulationContext Renderer::accumulationContext(Viewport& vp, const std::string& tag, const FrameInput& in,
                                                  bool cameraMoved, const std::string& prelude,
                                                  const std::string& shadowMap, const ProgramSetup& bindInputs) {
  AccumulationContext ctx;
  ctx.viewportTag = tag;
  ctx.rawVisibility = "visibility.raw" + tag;
  ctx.finalVisibility = "visibility.final" + tag;
  ctx.rawVisibilityTex = vp.rawVisibility_.get();
  ctx.finalVisibilityTex = vp.finalVisibility_.get();
  ctx.gPosition = gPosition_.get();
  ctx.gNormal = gNormal_.get();
  ctx.gMotion = gMotion_.get();
  ctx.shaders = &shaders_;
  ctx.params = &vp.technique.params;
  ctx.view = view_;
  ctx.proj = proj_;
  ctx.prevView = vp.prev_.view;
  ctx.prevProj = vp.prev_.proj;
  ctx.width = in.width;
  ctx.height = in.height;
  ctx.cameraMoved = cameraMoved;
  ctx.frameIndex = vp.frameIndex_;
  ctx.viewTargets = vp.shownViewTargets();
  ctx.techniquePrelude = prelude;
  ctx.bindTechniqueInputs = bindInputs;
  ctx.shadowMap = shadowMap;
  ctx.color = "color" + tag;
  ctx.colorTex = vp.color_.get();
  ctx.depthTex = vp.depth_.get();
  ctx.drawScene = [this, &in, &vp](const ProgramSpec& spec, const ProgramSetup& setup) {
    drawSceneForward(spec, setup, in.time, vp.prev_);
  };
  ctx.drawSky = [this] { drawSky(); };
  ctx.rawVisibilityTarget = vp.rawVisibility_.get();
  ctx.keepRawVisibility = keepGBuffer;
  return ctx;
}

}  // namespace sl
