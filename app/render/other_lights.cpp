// Scenes of several lights (Scene::otherLights). Each shadowed light other than Scene::light gets
// a viewport of its own inside the user's: the same technique and parameter values with their
// own part states, maps and histories, built by the same addLightPasses as the first light, so
// every part works per light without knowing of the others. Their visibilities meet only in
// the colour: each light's direct term is added into one sum (passes/light_direct.frag, the
// light's own defines and uniforms), and passes/shade_lights.frag shades Scene::light's
// visibility plus that sum. Unshadowed lights add their direct term unoccluded.
#include "part/uniforms.h"
#include "render/light_budget.h"
#include "render/renderer.h"

#include <algorithm>
#include <stdexcept>

namespace sl {

// Keeps one viewport per shadowed other light, following the user's technique: a new preset or
// part rebuilds it (its history gone), a parameter change is copied over every frame.
void Renderer::syncOtherLightViewports(Viewport& vp) {
  const std::vector<Light>& others = scene_->otherLights;
  vp.otherLights_.resize(others.size());
  // Scene::light is always shadowed; lights.shadowed counts it.
  int budget = vp.technique.params.has("lights.shadowed") ? vp.technique.params.i("lights.shadowed") - 1 : 1 << 20;
  for (size_t k = 0; k < others.size(); ++k) {
    std::unique_ptr<Viewport>& sub = vp.otherLights_[k];
    if (!others[k].shadow || budget-- <= 0) {
      sub.reset();
      continue;
    }
    const Technique& t = vp.technique;
    const bool same = sub && sub->technique.presetId == t.presetId && sub->technique.layout == t.layout &&
                      sub->technique.representation == t.representation &&
                      sub->technique.accumulation == t.accumulation;
    if (same)
      sub->technique.params = t.params;
    else
      sub = std::make_unique<Viewport>(t);
    sub->light_ = &others[k];
  }
}

// Layers of a light's maps, the texels its size buys: the last frame's, or before its first frame
// its layout asked once (then reset, so that nothing of the question stays in its state). Views
// that share a layer (an atlas of faces, a packed tetrahedron) count once: their layer is the map.
int Renderer::lightLayerCount(Viewport& light, const FrameInput& in) {
  if (!light.laidOut_) {
    const LayoutInput li = layoutInput(light, in);
    const int layers = light.layout->compute(li).layerCount();
    light.layout->reset();
    return layers;
  }
  return light.lightSpace.layerCount();
}

// The user's viewport and its other lights: an other light whose reach holds no visible point is
// not drawn (it lights no pixel; its history is forgotten), and with lights.texel_budget every
// drawn light's map size follows the screen it covers (render/light_budget.h). One shadowed light
// keeps the technique's size.
void Renderer::budgetLightMaps(Viewport& vp, const FrameInput& in) {
  vp.mapSize_ = 0;
  vp.budgetTexels_ = 0.0;
  vp.atlasRegion_ = glm::ivec4(0);
  vp.oneAtlasLayer_ = nullptr;
  std::vector<Viewport*> lights = {&vp};
  std::vector<const Light*> sources = {&scene_->light};
  for (size_t k = 0; k < vp.otherLights_.size(); ++k)
    if (vp.otherLights_[k]) {
      lights.push_back(vp.otherLights_[k].get());
      sources.push_back(&scene_->otherLights[k]);
    }
  if (lights.size() == 1) {
    vp.representation->shareDepthLayer(nullptr);
    vp.inOneAtlas_ = false;
    vp.oneAtlas_.reset();
    return;
  }
  const ParamSet& params = vp.technique.params;
  const double budget = params.has("lights.texel_budget") ? params.get("lights.texel_budget") * 1e6 : 0.0;
  const Bounds bounds = scene_->boundsAt(in.time);
  std::vector<LightDemand> demand(lights.size());
  for (size_t k = 0; k < lights.size(); ++k) {
    // Scene::light is always drawn whole: its visibility is what the views and the metrics show.
    glm::vec4 ndc;
    const double footprint = lightFootprint(*sources[k], bounds, view_, proj_, &ndc);
    lights[k]->heldFootprint_ =
        heldFootprint(lights[k]->heldFootprint_, k == 0 ? std::max(footprint, 1e-6) : footprint);
    demand[k].footprint = lights[k]->heldFootprint_;
    lights[k]->scissor_ = k == 0 ? glm::ivec4(0) : lightScissor(*sources[k], ndc, in.width, in.height);
    demand[k].layers = budget > 0.0 && demand[k].footprint > 0.0 ? lightLayerCount(*lights[k], in) : 1;
  }
  const int size = params.has("shadowmap.size") ? params.i("shadowmap.size") : 2048;
  std::vector<int> sizes = budgetMapSizes(demand, budget, size, 64);
  // lights.one_atlas: the lights that can share one layer, grown into its free cells.
  std::vector<bool> inAtlas(lights.size(), false);
  if (budget > 0.0 && params.has("lights.one_atlas") && params.b("lights.one_atlas")) {
    for (size_t k = 0; k < lights.size(); ++k) inAtlas[k] = canJoinOneAtlas(*lights[k], demand[k]);
    sizes = fillAtlasSizes(demand, sizes, inAtlas);
  }
  vp.sizeRange_[0] = size;
  vp.sizeRange_[1] = 0;
  for (size_t k = 0; k < lights.size(); ++k) {
    Viewport& light = *lights[k];
    light.drawn_ = sizes[k] > 0;
    light.mapSize_ = budget > 0.0 ? sizes[k] : 0;
    if (!light.drawn_) {
      light.prev_.epoch = 0;  // drawn again later: from a cut
      light.visibilityHeld_ = false;
      light.placedRegion_ = glm::ivec4(-1);  // its region may be another light's meanwhile
      continue;
    }
    vp.sizeRange_[0] = std::min(vp.sizeRange_[0], sizes[k]);
    vp.sizeRange_[1] = std::max(vp.sizeRange_[1], sizes[k]);
  }
  if (budget > 0.0) vp.budgetTexels_ = budgetedTexels(demand, sizes);
  for (size_t k = 0; k < lights.size(); ++k)
    if (!inAtlas[k]) sizes[k] = 0;
  assignOneAtlas(vp, lights, sizes);
}

namespace {

// The other lights' direct terms, each in its colour, summed into `fbo` (one RGBA16F target):
// cleared, then one additive fullscreen draw per light. visibility[k]: the k-th light's, null where it is not
// shadowed (by the scene file, or beyond lights.shadowed): lit through casters. scissors[k]: the
// pixels the light can reach (Viewport::scissor_; empty: none, its draw skipped; x < 0 or no
// entry: every pixel).
void drawOtherLightsDirect(ShaderLibrary& shaders, const Scene& scene, const Framebuffer& fbo,
                           const std::vector<const Texture2D*>& visibility, const std::vector<glm::ivec4>& scissors,
                           const ProgramSetup& bindGBuffer, const std::function<void()>& drawFullscreen) {
  fbo.bind();
  const float zero[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE);
  for (size_t k = 0; k < scene.otherLights.size(); ++k) {
    const glm::ivec4 rect = k < scissors.size() ? scissors[k] : glm::ivec4(-1);
    if (rect.z == 0 || rect.w == 0) continue;  // lights no visible point
    const Light& light = scene.otherLights[k];
    const Texture2D* vis = k < visibility.size() ? visibility[k] : nullptr;
    const std::string defines = lightDefines(light) + (vis ? "#define SL_SHADOWED_LIGHT\n" : "");
    ProgramSpec spec{"light direct",
                     {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/light_direct.frag"}},
                     defines};
    Program& p = shaders.get(spec);
    if (!p.valid()) continue;
    p.use();
    setLightUniforms(p, light);
    TextureUnits units;
    bindGBuffer(p, units);
    if (vis) units.bind(p, "u_visibility", vis->id());
    if (rect.x >= 0) {  // beyond the light's range its term is 0: only the pixels it can reach
      glEnable(GL_SCISSOR_TEST);
      glScissor(rect.x, rect.y, rect.z, rect.w);
    }
    drawFullscreen();
    glDisable(GL_SCISSOR_TEST);
  }
  glDisable(GL_BLEND);
}

}  // namespace

void Renderer::ensureOtherDirectTarget(Viewport& vp, int w, int h) {
  if (vp.otherDirect_ && vp.otherDirect_->width() == w && vp.otherDirect_->height() == h) return;
  vp.otherDirect_ = std::make_unique<Texture2D>(GL_RGBA16F, w, h, "lights.direct");
  vp.otherDirectFbo_ = Framebuffer("other lights' direct light");
  vp.otherDirectFbo_.attach({vp.otherDirect_.get()}, nullptr);
}

bool Renderer::shadeLights(const Framebuffer& target, const Texture2D& visibility, const Texture2D& otherDirect) {
  ProgramSpec spec{"shade lights",
                   {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/shade_lights.frag"}},
                   lightDefines(scene_->light)};
  Program& p = shaders_.get(spec);
  if (!p.valid()) return false;
  target.bind();
  p.use();
  setLightUniforms(p, scene_->light);
  TextureUnits units;
  bindGBuffer(p, units, &visibility);
  units.bind(p, "u_otherDirect", otherDirect.id());
  drawFullscreen();
  return true;
}

void Renderer::addOtherLightsPasses(FrameGraph& g, Viewport& vp, const std::string& tag, const FrameInput& in) {
  const std::vector<Light>& others = scene_->otherLights;
  if (others.empty()) return;
  ensureOtherDirectTarget(vp, in.width, in.height);
  std::vector<std::string> reads = {"gbuffer"};
  std::vector<const Texture2D*> visibility(others.size(), nullptr);
  std::vector<glm::ivec4> scissors(others.size(), glm::ivec4(-1));
  for (size_t k = 0; k < others.size(); ++k) {
    Viewport* sub = vp.otherLights_[k].get();
    if (!sub) continue;
    if (!sub->drawn_) {
      scissors[k] = glm::ivec4(0);
      continue;
    }
    if (sub->scissor_.z > 0) scissors[k] = sub->scissor_;
    ensureViewportTargets(*sub, in.width, in.height);
    addLightPasses(g, *sub, tag + ".light" + std::to_string(k + 1), in);
    reads.push_back(sub->output_.visibility);
    visibility[k] = sub->visibilityTexture();
  }
  const std::string sum = "lights.direct" + tag;
  g.add({"lights direct" + tag, reads, {sum}, [this, &vp, visibility, scissors] {
           ProgramSetup gbuffer = [this](const Program& p, TextureUnits& units) { bindGBuffer(p, units); };
           drawOtherLightsDirect(shaders_, *scene_, vp.otherDirectFbo_, visibility, scissors, gbuffer,
                                 [this] { drawFullscreen(); });
         }});
  // Writes the colour whole (sky included): the first light's own shade pass is culled unless
  // it also writes something read (a forward pass's visibility).
  const Texture2D* primary = vp.visibilityTexture();
  g.add({"shade lights" + tag, {"gbuffer", vp.output_.visibility, sum}, {"color" + tag}, [this, &vp, primary] {
           shadeLights(vp.colorFbo_, *primary, *vp.otherDirect_);
         }});
}

// shadeWithVisibility's other lights: their visibilities uploaded, their direct light summed.
const Texture2D& Renderer::substitutedOtherDirect(int w, int h, const std::vector<std::vector<float>>& others) {
  const std::vector<Light>& lights = scene_->otherLights;
  if (!substOtherDirect_ || substOtherDirect_->width() != w || substOtherDirect_->height() != h) {
    substOtherDirect_ = std::make_unique<Texture2D>(GL_RGBA16F, w, h, "substituted other lights' direct light");
    substOtherDirectFbo_ = Framebuffer("shade with visibility: other lights");
    substOtherDirectFbo_.attach({substOtherDirect_.get()}, nullptr);
  }
  substOtherVisibility_.resize(lights.size());
  std::vector<const Texture2D*> visibility(lights.size(), nullptr);
  for (size_t k = 0; k < lights.size(); ++k) {
    if (!lights[k].shadow) continue;
    if (k >= others.size() || others[k].size() != size_t(w) * size_t(h))
      throw std::invalid_argument("shadeWithVisibility: no " + std::to_string(w) + "x" + std::to_string(h) +
                                  " visibility for light " + std::to_string(k + 2) + " of the scene");
    auto& tex = substOtherVisibility_[k];
    if (!tex || tex->width() != w || tex->height() != h)
      tex = std::make_unique<Texture2D>(GL_R32F, w, h, "substituted visibility of another light");
    glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
    glTextureSubImage2D(tex->id(), 0, 0, 0, w, h, GL_RED, GL_FLOAT, others[k].data());
    visibility[k] = tex.get();
  }
  ProgramSetup gbuffer = [this](const Program& p, TextureUnits& units) { bindGBuffer(p, units); };
  drawOtherLightsDirect(shaders_, *scene_, substOtherDirectFbo_, visibility, {}, gbuffer, [this] { drawFullscreen(); });
  return *substOtherDirect_;
}

}  // namespace sl
