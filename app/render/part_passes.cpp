// How the renderer hands a viewport's frame to the technique's parts: what a part sees while it
// adds its passes (PartContext), what an accumulation sees (AccumulationContext), and the shadow
// pass that draws the light views into the representation's layers.
#include "render/gpu_scene.h"
#include "render/renderer.h"

namespace sl {

// The plan of this frame's shadow pass: the representation's caster draw, the light views'
// projection kinds, and the layout's layers (whole or tiled). Made while the pass runs: a paged
// layout knows its tiles only after its own passes.
ShadowDrawPlan Renderer::shadowDrawPlan(Viewport& vp) const {
  const CasterDraw casters = vp.technique.representation->casterDraw();
  ShadowDrawPlan plan;
  plan.stages = casterStages(vp.lightSpace, casters.fragment);
  plan.sortStage = casterSortStage(vp.lightSpace);
  plan.casters = casters.casters;
  plan.layers.resize(vp.lightSpace.views.size());
  vp.layout->planShadowLayers(plan.layers, vp.representation->keepsLayers());
  // A view in an atlas is drawn as one tile, its rectangle (unless the layout leaves it undrawn).
  for (size_t v = 0; v < plan.layers.size(); ++v) {
    const glm::ivec4& rect = vp.lightSpace.views[v].atlasRect;
    if (!plan.layers[v].tiled && rect.z > 0 && rect.w > 0) plan.layers[v] = {.tiled = true, .tiles = {atlasTile(rect)}};
    // A layer other lights draw into: a view outside every rectangle of it is not drawn at all.
    if (vp.inOneAtlas_ && !(rect.z > 0 && rect.w > 0)) plan.layers[v] = {.tiled = true, .tiles = {}};
  }
  return plan;
}

// Binds the layer view `view` is drawn into: the first view of a layer clears it when some view
// draws it whole or into its atlas square (begin), or binds it for tiles (bind: cleared unless
// the representation keeps its layers); the next views packed into the same layer draw beside it
// (continue).
void Renderer::bindShadowLayerFor(Viewport& vp, const ShadowDrawPlan& plan, int view, std::vector<bool>& begun) {
  const LightSpace& space = vp.lightSpace;
  const int layer = space.layerOf(size_t(view));
  if (begun[size_t(layer)]) {
    vp.representation->continueShadowLayer(layer);
    return;
  }
  begun[size_t(layer)] = true;
  // Cleared whole when a view draws it whole, or an atlas view draws its square (an atlas is
  // redrawn all at once: the squares move with the faces' needs).
  bool whole = false;
  for (size_t v = 0; v < plan.layers.size(); ++v) {
    const bool atlasDrawn = space.views[v].atlasRect.z > 0 && !plan.layers[v].tiles.empty();
    whole = whole || (space.layerOf(v) == layer && (!plan.layers[v].tiled || atlasDrawn));
  }
  if (!whole) {
    vp.representation->bindShadowLayer(layer);
  } else if (vp.inOneAtlas_) {  // a layer other lights draw into too: this light's region alone
    vp.representation->bindShadowLayer(layer);
    const glm::ivec4 r = vp.atlasRegion_;
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x, r.y, r.z, r.w);
    glDepthMask(GL_TRUE);
    glClear(GL_DEPTH_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
  } else {
    vp.representation->beginShadowLayer(layer);
  }
}

// Draws one light view of the plan into its layer (whole, or tile by tile into its rectangles).
void Renderer::drawShadowLayer(Viewport& vp, const ShadowDrawPlan& plan, const ProgramSpec& spec, int view,
                               std::vector<bool>& begun, double time) {
  const ParamSet& params = vp.frameParams_;
  static const GLenum culled[] = {GL_BACK, GL_FRONT, 0};  // front faces, back faces, both
  const GLenum cull = culled[params.i("shadowmap.cull")];
  const auto only = plan.casters == CasterSet::Opaque ? GpuScene::Only::Opaque : GpuScene::Only::All;
  const glm::mat4* cullTo =
      params.b("shadowmap.cull_instances") ? &vp.lightSpace.views[size_t(view)].viewProj : nullptr;
  const ShadowLayerDraw& draw = plan.layers[size_t(view)];
  bindShadowLayerFor(vp, plan, view, begun);
  if (!draw.tiled) {
    const ProgramSetup setup = [this, &vp, view](const Program& p, TextureUnits& units) {
      bindTechnique(p, units, vp);
      p.set("u_shadowView", view);
    };
    PassPrograms programs(shaders_, spec, setup);
    Program* sort = plan.sortStage.empty()
                        ? nullptr
                        : &shaders_.get({spec.name + " sort", {{GL_COMPUTE_SHADER, plan.sortStage}}, spec.prelude});
    if (sort && sort->valid()) {
      PassPrograms plain(shaders_, {spec.name + " plain", withoutTessellation(spec.stages), spec.prelude}, setup);
      sort->use();
      TextureUnits units;
      setup(*sort, units);
      gpu_->drawSorted(programs, plain, *sort, time, cull, only, cullTo);
    } else {
      gpu_->draw(programs, time, time, cull, only, cullTo);
    }
    return;
  }
  // A piecewise layer (bound without clearing when the representation keeps its layers):
  // each tile's rectangle cleared and drawn.
  glEnable(GL_SCISSOR_TEST);
  for (const ShadowTile& tile : draw.tiles) {
    if (tile.wholeLayerViewport)
      glViewport(0, 0, vp.lightSpace.size, vp.lightSpace.size);
    else
      glViewport(tile.rect.x, tile.rect.y, tile.rect.z, tile.rect.w);
    glScissor(tile.rect.x, tile.rect.y, tile.rect.z, tile.rect.w);
    glDepthMask(GL_TRUE);
    // The scissor limits the clear to the tile. A light's region of a shared layer was cleared
    // whole when it began (bindShadowLayerFor): views packed into it draw beside each other.
    if (!vp.inOneAtlas_) glClear(GL_DEPTH_BUFFER_BIT);
    PassPrograms programs(shaders_, spec, [this, &vp, view, &tile](const Program& p, TextureUnits& units) {
      bindTechnique(p, units, vp);
      p.set("u_shadowView", view);
      p.set("u_pageTransform", tile.transform);
    });
    const glm::mat4 tileClip = cullTo ? tile.clip(*cullTo) : glm::mat4(1.0f);
    gpu_->draw(programs, time, time, cull, only, cullTo ? &tileClip : nullptr);
  }
  glDisable(GL_SCISSOR_TEST);
}

// Layout passes, then the shadow pass (the draw plan, one entry per light view), then the
// representation's passes; the renderer only orders what the parts declare.
void Renderer::addShadowPass(FrameGraph& g, Viewport& vp, const std::string& tag, const std::vector<std::string>& reads,
                             const FrameInput& in) {
  const std::string prelude = techniquePrelude(vp);
  g.add({"shadowmap" + tag, reads, {"shadowmap" + tag}, [this, &vp, prelude, &in] {
           const Technique& t = vp.technique;
           const ShadowDrawPlan plan = shadowDrawPlan(vp);
           const ProgramSpec spec{"shadowmap " + t.layout->id() + "+" + t.representation->id(), plan.stages, prelude};
           glEnable(GL_DEPTH_TEST);
           // Views packed into one layer each keep to their triangle (passes/shadow.vert).
           const bool packed = vp.lightSpace.packed();
           for (GLenum clip : {GL_CLIP_DISTANCE0, GL_CLIP_DISTANCE1}) packed ? glEnable(clip) : glDisable(clip);
           std::vector<bool> begun(size_t(vp.lightSpace.layerCount()), false);
           for (int view = 0; view < static_cast<int>(plan.layers.size()); ++view)
             drawShadowLayer(vp, plan, spec, view, begun, in.time);
           for (GLenum clip : {GL_CLIP_DISTANCE0, GL_CLIP_DISTANCE1}) glDisable(clip);
           glDisable(GL_DEPTH_TEST);
         }});
}

// What every part of a viewport's technique sees while it adds its passes.
PartContext Renderer::partContext(Viewport& vp, const std::string& tag, const FrameInput& in, bool cameraMoved,
                                  const std::string& prelude) {
  PartContext part;
  part.viewportTag = tag;
  part.scene = scene_;
  part.light = &lightOf(vp);
  part.time = in.time;
  part.shaders = &shaders_;
  part.params = &vp.frameParams_;
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
  part.replaceLightSpace = [this, &vp](const LightSpace& ls) {
    vp.lightSpace = ls;
    placeInOneAtlas(vp);  // a refit's views into the light's region again
    vp.lightViews_->upload(vp.lightSpace);
  };
  return part;
}

// What an accumulation reads and writes for this viewport's frame.
AccumulationContext Renderer::accumulationContext(FrameGraph& g, Viewport& vp, const std::string& tag,
                                                  const FrameInput& in, bool cameraMoved, const std::string& prelude,
                                                  const std::string& shadowMap, const ProgramSetup& bindGBuffer) {
  // Binds the G-buffer and every part's inputs on a visibility-computing program.
  ProgramSetup bindInputs = [this, &vp, bindGBuffer](const Program& p, TextureUnits& units) {
    bindTechnique(p, units, vp);
    bindGBuffer(p, units);
  };
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
  ctx.params = &vp.frameParams_;
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
  ctx.addForwardShade = [this, &g, &vp, tag, prelude, shadowMap, bindInputs, &in] {
    // Another light of the scene: only its visibility is read (the colour sums the lights),
    // so the fullscreen test over the G-buffer replaces drawing the scene again (half the
    // cost per light on llvmpipe: docs/performance.md, "Several lights").
    if (vp.light_ && vp.light_ != &scene_->light) {
      addVisibilityPass(g, vp, tag, prelude, shadowMap, bindInputs);
      return AccumulationOutput{"visibility.raw" + tag, vp.rawVisibility_.get(), "gbuffer", gDepth_.get()};
    }
    return addForwardShadePass(g, vp, tag, prelude, shadowMap, bindInputs, in);
  };
  ctx.addVisibilityTest = [this, &g, &vp, tag, prelude, shadowMap, bindInputs] {
    addVisibilityPass(g, vp, tag, prelude, shadowMap, bindInputs);
  };
  ctx.addDeferredShade = [this, &g, &vp, tag](const std::string& visibility, const Texture2D* texture) {
    return addDeferredShadePass(g, vp, tag, visibility, texture);
  };
  return ctx;
}

}  // namespace sl
