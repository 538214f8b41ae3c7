#include "render/renderer.h"

#include "part/uniforms.h"
#include "render/gpu_scene.h"
#include "scene/scene_effects.h"

#include <glm/gtc/matrix_transform.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace sl {

const std::vector<std::string>& commonViewNames() {
  static const std::vector<std::string> names = {"shadowmap", "texels", "aliasing", "visibility", "lightspace"};
  return names;
}

Viewport::Viewport(Technique t) : technique(std::move(t)) { setTechnique(technique); }

void Viewport::setTechnique(Technique t) {
  technique = std::move(t);
  layout = technique.layout->createState();
  representation = technique.representation->createState();
  accumulation = technique.accumulation->createState();
  // The last frame's visibility may be a texture of the old accumulation's state.
  output_ = {};
  visibilityHeld_ = false;
  laidOut_ = false;
}

const Texture2D* Viewport::viewTexture(const std::string& name) const {
  auto it = views_.find(name);
  return it == views_.end() ? nullptr : it->second.get();
}

std::vector<std::string> Viewport::availableViews() const {
  std::vector<std::string> v = commonViewNames();
  for (const PartState* part :
       {static_cast<const PartState*>(layout.get()), static_cast<const PartState*>(representation.get()),
        static_cast<const PartState*>(accumulation.get())})
    for (const auto& extra : part->views()) v.push_back(extra);
  return v;
}

std::map<std::string, Texture2D*> Viewport::shownViewTargets() {
  std::map<std::string, Texture2D*> targets;
  for (const auto& name : shownViews)
    if (views_.count(name)) targets[name] = views_[name].get();
  return targets;
}

long long Viewport::shadowTexels() const {
  long long texels = layout->texels() + representation->texels() + accumulation->texels();
  if (oneAtlas_) texels += static_cast<long long>(oneAtlas_->depth.width()) * oneAtlas_->depth.height();
  for (const auto& other : otherLights_)
    if (other) texels += other->shadowTexels();
  return texels;
}

const Texture2D* Viewport::otherLightVisibility(size_t k) const {
  if (k >= otherLights_.size() || !otherLights_[k] || !otherLights_[k]->visibilityHeld_) return nullptr;
  return otherLights_[k]->visibilityTexture();
}

// The shared layer of lights.one_atlas: its side, and how many lights' regions fill how much of it.
std::string Viewport::oneAtlasStatus() const {
  int lights = 0;
  double used = 0.0;
  auto count = [&](const Viewport& light) {
    lights += light.atlasRegion_.z > 0 ? 1 : 0;
    used += double(light.atlasRegion_.z) * double(light.atlasRegion_.w);
  };
  count(*this);
  for (const auto& other : otherLights_)
    if (other) count(*other);
  const double side = oneAtlas_->layer.size;
  char text[128];
  std::snprintf(text, sizeof text, "; one atlas %d² for %d lights (%.0f %% of it)", oneAtlas_->layer.size, lights,
                100.0 * used / (side * side));
  return text;
}

std::string Viewport::status() const {
  std::string out;
  for (const PartState* part :
       {static_cast<const PartState*>(layout.get()), static_cast<const PartState*>(representation.get()),
        static_cast<const PartState*>(accumulation.get())}) {
    const std::string s = part->status();
    if (!s.empty()) out += (out.empty() ? "" : "; ") + s;
  }
  if (!otherLights_.empty()) {
    size_t shadowed = 1, unreached = 0;
    for (const auto& other : otherLights_) {
      shadowed += other ? 1 : 0;
      unreached += other && !other->drawn_ ? 1 : 0;
    }
    out += (out.empty() ? "" : "; ") + std::to_string(otherLights_.size() + 1) + " lights, " +
           std::to_string(shadowed) + " shadowed (views show the first)";
    if (unreached) out += ", " + std::to_string(unreached) + " reaching nothing in view (not drawn)";
    if (budgetTexels_ > 0.0) {
      char text[96];
      std::snprintf(text, sizeof text, "; maps %d to %d per side, %.1f M texels", sizeRange_[0], sizeRange_[1],
                    budgetTexels_ * 1e-6);
      out += text;
    }
    if (oneAtlas_) out += oneAtlasStatus();
  }
  return out;
}

void Renderer::bindGBuffer(const Program& p, TextureUnits& units) const {
  units.bind(p, "u_gPosition", gPosition_->id());
  units.bind(p, "u_gNormal", gNormal_->id());
  units.bind(p, "u_gAlbedo", gAlbedo_->id());
  units.bind(p, "u_gSurface", gSurface_->id());
}

void Renderer::bindGBuffer(const Program& p, TextureUnits& units, const Texture2D* visibility) const {
  bindGBuffer(p, units);
  units.bind(p, "u_visibility", visibility->id());
}

void Renderer::bindTechnique(const Program& p, TextureUnits& units, const Viewport& vp) const {
  setTechniqueUniforms(p, vp.frameParams_, vp.lightSpace, lightOf(vp));
  vp.lightViews_->bind();
  vp.layout->bind(p, units);
  vp.representation->bind(p, units);
  vp.accumulation->bind(p, units);
}

bool Renderer::defaultValidateFrameGraph() {
  const char* env = std::getenv("SHADOWLAB_VALIDATE_GRAPH");
  return std::string_view(SHADOWLAB_BUILD_TYPE) == "Debug" || (env && std::string_view(env) == "1");
}

glm::ivec2 Renderer::sortedCasterTriangles() const { return gpu_ ? gpu_->sortedTriangles() : glm::ivec2(0); }

Renderer::Renderer(ShaderLibrary& shaders) : shaders_(shaders) {
  glCreateVertexArrays(1, &emptyVao_);
  label(GL_VERTEX_ARRAY, emptyVao_, "fullscreen triangle");
  glCreateBuffers(1, &linesVbo_);
  glNamedBufferData(linesVbo_, 4096 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
  glCreateVertexArrays(1, &linesVao_);
  glVertexArrayVertexBuffer(linesVao_, 0, linesVbo_, 0, 6 * sizeof(float));
  for (GLuint a = 0; a < 2; ++a) {
    glEnableVertexArrayAttrib(linesVao_, a);
    glVertexArrayAttribFormat(linesVao_, a, 3, GL_FLOAT, GL_FALSE, a * 3 * sizeof(float));
    glVertexArrayAttribBinding(linesVao_, a, 0);
  }
  label(GL_VERTEX_ARRAY, linesVao_, "overlay lines");
  label(GL_BUFFER, linesVbo_, "overlay lines");
}

Renderer::~Renderer() {
  glDeleteVertexArrays(1, &emptyVao_);
  glDeleteVertexArrays(1, &linesVao_);
  glDeleteBuffers(1, &linesVbo_);
}

void Renderer::setScene(const Scene& scene) {
  gpu_.reset();
  gpu_ = std::make_unique<GpuScene>(scene);
  scene_ = &scene;
  ++epoch_;
  static std::atomic<uint64_t> generations{0};
  sceneGeneration_ = ++generations;
}

void Renderer::ensureTargets(int w, int h) {
  if (w == width_ && h == height_ && gPosition_) return;
  width_ = w;
  height_ = h;
  gPosition_ = std::make_unique<Texture2D>(GL_RGBA32F, w, h, "gbuffer.position");
  // 32-bit normals: the sign of N.L at a grazing light decides pixels, and the reference reads it.
  gNormal_ = std::make_unique<Texture2D>(GL_RGBA32F, w, h, "gbuffer.normal");
  gAlbedo_ = std::make_unique<Texture2D>(GL_RGBA8, w, h, "gbuffer.albedo");
  gSurface_ = std::make_unique<Texture2D>(GL_RGBA32UI, w, h, "gbuffer.surface");
  gMotion_ = std::make_unique<Texture2D>(GL_RGBA32F, w, h, "gbuffer.motion");
  gDepth_ = std::make_unique<Texture2D>(GL_DEPTH_COMPONENT32F, w, h, "gbuffer.depth");
  gFbo_ = Framebuffer("gbuffer");
  gFbo_.attach({gPosition_.get(), gNormal_.get(), gAlbedo_.get(), gSurface_.get()}, gDepth_.get());
  // Per-pixel motion costs a fifth target; only the pixel-correct debug views read it.
  gFboMotion_ = Framebuffer("gbuffer + motion");
  gFboMotion_.attach({gPosition_.get(), gNormal_.get(), gAlbedo_.get(), gSurface_.get(), gMotion_.get()},
                     gDepth_.get());
  ++epoch_;  // a resize is a cut: history no longer matches the screen
}

void Renderer::ensureViewportTargets(Viewport& vp, int w, int h) {
  if (!vp.lightViews_) vp.lightViews_ = std::make_unique<LightViewsBuffer>();
  if (w != vp.targetsW_ || h != vp.targetsH_ || !vp.color_) {
    vp.targetsW_ = w;
    vp.targetsH_ = h;
    vp.rawVisibility_ = std::make_unique<Texture2D>(GL_RG16F, w, h, "visibility.raw");
    vp.finalVisibility_ = std::make_unique<Texture2D>(GL_RG16F, w, h, "visibility.final");
    vp.color_ = std::make_unique<Texture2D>(GL_RGBA8, w, h, "color");
    vp.visibilityFbo_ = Framebuffer("visibility");
    vp.visibilityFbo_.attach({vp.rawVisibility_.get()}, nullptr);
    vp.colorFbo_ = Framebuffer("color");
    vp.colorFbo_.attach({vp.color_.get()}, nullptr);
    vp.depth_ = std::make_unique<Texture2D>(GL_DEPTH_COMPONENT32F, w, h, "depth");
    vp.forwardFbo_ = Framebuffer("forward: color + visibility + depth");
    vp.forwardFbo_.attach({vp.color_.get(), vp.rawVisibility_.get()}, vp.depth_.get());
    vp.views_.clear();
    vp.accumulation->reset();
    vp.visibilityHeld_ = false;  // new textures: nothing in them yet
  }
  for (const auto& name : vp.shownViews)
    if (!vp.views_.count(name)) vp.views_[name] = std::make_unique<Texture2D>(GL_RGBA8, w, h, "view." + name);
}

std::string Renderer::techniquePrelude(const Viewport& vp) const {
  // Per-technique and per-scene constants become defines, not uniform branches: a software
  // rasterizer executes both sides of every branch. Representations reconstruct visibility per
  // fragment; vertex stages only need the layout. A compute pass that reconstructs (the forward
  // splat) asks for the representation too with SL_REPRESENTATION_IN_COMPUTE.
  const Technique& t = vp.technique;
  std::string defines = enumDefines(t.params);  // SL_BIAS_MODE_IS_SLOPE, ...
  defines += lightDefines(lightOf(vp));
  // Soft techniques compile their area-light path only where the scene calls for it.
  if (sceneEffects(*scene_, lightOf(vp)).areaLight) defines += "#define SL_AREA_LIGHT\n";
  if (vp.lightSpace.perspective()) defines += "#define SL_PERSPECTIVE_MAP\n";
  if (vp.lightSpace.packed()) defines += "#define SL_PACKED_VIEWS\n";
  defines += "#define SL_LIGHT_VIEWS " + std::to_string(vp.lightSpace.views.size()) + "\n";
  defines += vp.layout->defines() + vp.representation->defines() + vp.accumulation->defines();
  return defines + "#include \"" + t.layout->glslModule() +
         "\"\n#if defined(SL_FRAGMENT) || defined(SL_REPRESENTATION_IN_COMPUTE)\n#include \"" +
         t.representation->glslModule() + "\"\n#endif\n";
}

void Renderer::drawGBuffer(const glm::mat4& viewProj, double time, const PreviousFrame& prev, bool positionsOnly,
                           bool withMotion) {
  withMotion = withMotion && !positionsOnly;
  const Framebuffer& fbo = withMotion ? gFboMotion_ : gFbo_;
  const GLsizei targets = withMotion ? 5 : 4;
  fbo.bind();
  // Positions alone: the other draw buffers off (llvmpipe writes every enabled target of every
  // fragment: 17 -> 6.5 ms at 1280x720 on basic), restored after the draw.
  const GLenum onlyPosition[5] = {GL_COLOR_ATTACHMENT0, GL_NONE, GL_NONE, GL_NONE, GL_NONE};
  if (positionsOnly) glNamedFramebufferDrawBuffers(fbo.id(), targets, onlyPosition);
  const float zero[4] = {0, 0, 0, 0};
  const GLuint none[4] = {0, 0, 0, 0};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, zero);
  if (!positionsOnly) {
    for (int i = 1; i < 3; ++i) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, i, zero);
    glClearNamedFramebufferuiv(fbo.id(), GL_COLOR, 3, none);  // surface ids: an integer target
    if (withMotion) glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 4, zero);
  }
  glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  glEnable(GL_DEPTH_TEST);
  std::string defines = positionsOnly ? "#define SL_GBUFFER_POSITION_ONLY\n"
                        : withMotion  ? "#define SL_WRITE_MOTION\n"
                                      : "";
  PassPrograms programs(
      shaders_,
      {"gbuffer", {{GL_VERTEX_SHADER, "passes/gbuffer.vert"}, {GL_FRAGMENT_SHADER, "passes/gbuffer.frag"}}, defines},
      [&](const Program& p, TextureUnits&) {
        p.set("u_viewProj", viewProj);
        p.set("u_prevViewProj", prev.proj * prev.view);
      });
  gpu_->draw(programs, time, prev.time);
  glDisable(GL_DEPTH_TEST);
  if (positionsOnly) {
    const GLenum every[5] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1, GL_COLOR_ATTACHMENT2, GL_COLOR_ATTACHMENT3,
                             GL_COLOR_ATTACHMENT4};
    glNamedFramebufferDrawBuffers(fbo.id(), targets, every);
  }
  // Only a whole G-buffer is one a later reader (shadeWithVisibility) may reuse.
  gbufferHolds_ = positionsOnly ? GBufferContent{} : GBufferContent{viewProj, time, epoch_};
}

void Renderer::drawSky() {
  ProgramSpec spec{"sky", {{GL_VERTEX_SHADER, "passes/sky.vert"}, {GL_FRAGMENT_SHADER, "passes/sky.frag"}}, ""};
  Program& p = shaders_.get(spec);
  if (!p.valid()) return;
  // Only background pixels (depth still at the far plane) and only the colour attachment.
  GLint attachments = 0;
  glGetIntegerv(GL_MAX_DRAW_BUFFERS, &attachments);
  for (GLint i = 1; i < attachments; ++i) glColorMaski(static_cast<GLuint>(i), GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glDepthMask(GL_FALSE);
  p.use();
  drawFullscreen();
  glDepthMask(GL_TRUE);
  glDepthFunc(GL_LESS);
  glDisable(GL_DEPTH_TEST);
  for (GLint i = 1; i < attachments; ++i) glColorMaski(static_cast<GLuint>(i), GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

void Renderer::drawSceneForward(const ProgramSpec& spec, const ProgramSetup& setup, double time,
                                const PreviousFrame& prev) {
  glEnable(GL_DEPTH_TEST);
  PassPrograms programs(shaders_, spec, [this, &setup, &prev](const Program& p, TextureUnits& units) {
    setup(p, units);
    p.set("u_viewProj", proj_ * view_);
    p.set("u_prevViewProj", prev.proj * prev.view);
    p.set("u_prevView", prev.view);
  });
  gpu_->draw(programs, time, prev.time);
  glDisable(GL_DEPTH_TEST);
}

void Renderer::drawFullscreen() {
  glBindVertexArray(emptyVao_);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glBindVertexArray(0);
}

// Runs the culled passes, each in a KHR_debug group named after it, and times them (stats_).
void Renderer::executeTimed(const FrameGraph& graph) {
  const bool useGpuTimer = timePasses && (forceTimerQueries || !isSoftwareRenderer());
  FrameStats last = std::move(stats_);
  stats_ = FrameStats{};
  stats_.timer = useGpuTimer ? "gpu-query" : "cpu-fence";
  if (useGpuTimer && !queryTimer_) queryTimer_ = std::make_unique<PassQueryTimer>();
  auto frameStart = std::chrono::steady_clock::now();
  transients_.beginFrame();
  graph.execute(
      [&](const Pass& pass, const std::function<void()>& run) {
        GlDebugGroup group(pass.name);
        if (!timePasses) {
          run();
          stats_.passes.push_back({pass.name, 0.0});
        } else if (useGpuTimer) {
          queryTimer_->beginPass();
          run();
          queryTimer_->endPass(pass.name);
          stats_.passes.push_back({pass.name, 0.0});
        } else {
          // llvmpipe's timer queries do not measure the work; a fence with a steady clock does.
          glFinish();
          auto t0 = std::chrono::steady_clock::now();
          run();
          glFinish();
          stats_.passes.push_back(
              {pass.name, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()});
        }
      },
      &transients_);
  if (useGpuTimer) {
    // The frame's own times (waiting for them), or the newest frame's that have arrived; until
    // the first arrives the passes of this frame at 0 ms, after it the last arrived ones.
    PassQueryTimer::Times times;
    if (queryTimer_->endFrame(waitForPassTimes, times)) {
      stats_.passes.clear();
      for (auto& [name, ms] : times) stats_.passes.push_back({std::move(name), ms});
    } else if (last.timer == stats_.timer && !last.passes.empty()) {
      stats_.passes = std::move(last.passes);
    }
    stats_.frameMs = 0;
    for (const auto& p : stats_.passes) stats_.frameMs += p.ms;
    return;
  }
  if (timePasses) glFinish();
  stats_.frameMs = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frameStart).count();
}

void Renderer::render(const FrameInput& in, const std::vector<Viewport*>& viewports) {
  if (!scene_) throw std::runtime_error("renderer: no scene loaded");
  ensureTargets(in.width, in.height);
  view_ = cameraView(in.camera);
  proj_ = cameraProjection(in.camera, static_cast<float>(in.width) / static_cast<float>(in.height));
  // A cut, a new scene or size, or a viewport's first frame: motion is relative to this frame.
  const PreviousFrame now{view_, proj_, in.time, epoch_};
  if (prev_.epoch != epoch_ || in.cut) prev_ = now;
  // Every light's viewport of every viewport (several lights: render/other_lights.cpp).
  std::vector<Viewport*> lights;
  for (Viewport* vp : viewports) {
    syncOtherLightViewports(*vp);
    budgetLightMaps(*vp, in);
    lights.push_back(vp);
    for (const auto& other : vp->otherLights_)
      if (other && other->drawn_) lights.push_back(other.get());
  }
  for (Viewport* vp : lights) {
    if (vp->prev_.epoch == epoch_ && !in.cut) continue;
    vp->prev_ = now;
    vp->accumulation->reset();
    vp->layout->reset();  // e.g. SDSM bounds of frames before the cut
  }
  FrameGraph graph;
  // One pass makes "gbuffer" (every target but motion), "gbuffer.position" (world positions and
  // coverage, what the virtual maps' page marking reads) and "gbuffer.motion" (each pixel's
  // previous-frame position, what the pixel-correct views read): when nothing that runs reads
  // the rest, it draws the positions alone, and motion only for a pass that reads it (a fifth
  // 32-bit target costs llvmpipe about 4 ms at 1280x720).
  gbufferFresh_ = false;
  graph.add({"gbuffer", {}, {"gbuffer", "gbuffer.position", "gbuffer.motion"}, [this, &in, &graph] {
               gbufferFresh_ = graph.neededLive("gbuffer");
               drawGBuffer(proj_ * view_, in.time, prev_, !gbufferFresh_, graph.neededLive("gbuffer.motion"));
             }});
  if (keepGBuffer) graph.requestSink("gbuffer");
  for (size_t i = 0; i < viewports.size(); ++i) {
    ensureViewportTargets(*viewports[i], in.width, in.height);
    addViewportPasses(graph, *viewports[i], i, in);
  }

  if (validateFrameGraph) graph.compile();
  executeTimed(graph);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  // Every program this frame drew with has had all its uniforms set by now.
  shaders_.checkUnsetUniforms();
  prev_ = now;
  for (Viewport* vp : lights) {
    vp->prev_ = now;
    ++vp->frameIndex_;
    vp->visibilityHeld_ = true;
  }
}

// The layout's light views for this frame, uploaded, and the representation's targets for them.
// What a layout fits this frame's views to (the jitter is the caller's); sets frameParams_.
LayoutInput Renderer::layoutInput(Viewport& vp, const FrameInput& in) {
  vp.frameParams_ = vp.technique.params;
  if (vp.mapSize_ > 0) vp.frameParams_.set("shadowmap.size", vp.mapSize_);
  LayoutInput li;
  li.scene = scene_;
  li.light = &lightOf(vp);
  li.sceneGeneration = sceneGeneration_;
  li.time = in.time;
  li.cameraView = in.fitCamera ? cameraView(*in.fitCamera) : view_;
  li.cameraProj = in.fitCamera ? cameraProjection(*in.fitCamera, static_cast<float>(in.width) / in.height) : proj_;
  li.params = &vp.frameParams_;
  li.filterReachTexels = vp.technique.representation->filterReachTexels(vp.frameParams_, lightOf(vp));
  return li;
}

void Renderer::layOutViewport(Viewport& vp, const FrameInput& in, bool cameraMoved) {
  Technique& t = vp.technique;
  LayoutInput li = layoutInput(vp, in);
  li.jitter = vp.accumulation->jitter(vp.frameParams_, cameraMoved);
  vp.lightSpace = vp.layout->compute(li);
  vp.laidOut_ = true;
  if (vp.lightSpace.views.empty() || vp.lightSpace.views.size() > static_cast<size_t>(kMaxLightViews))
    throw std::runtime_error("layout '" + t.layout->id() + "' returned " + std::to_string(vp.lightSpace.views.size()) +
                             " light views (1 to " + std::to_string(kMaxLightViews) + " allowed)");
  placeInOneAtlas(vp);
  vp.lightViews_->upload(vp.lightSpace);
  vp.representation->setScene(*scene_, lightOf(vp));
  vp.representation->configure(vp.frameParams_);
  vp.representation->prepare(vp.lightSpace.size, vp.lightSpace.layerCount(),
                             static_cast<int>(vp.lightSpace.views.size()));
}

void Renderer::addViewportPasses(FrameGraph& g, Viewport& vp, size_t index, const FrameInput& in) {
  const std::string tag = "[" + std::to_string(index) + "]";
  vp.light_ = &scene_->light;
  const std::string prelude = addLightPasses(g, vp, tag, in);
  // Several lights: every shadowed one's passes, and the colour shaded with all of them; the
  // volumes then march over that colour (toward Scene::light, the one their prelude names).
  addOtherLightsPasses(g, vp, tag, in);
  addVolumesPass(g, vp, tag, prelude, vp.output_.depthTex, {vp.output_.depth, vp.shadowResource_});
  g.requestSink("color" + tag);
  g.requestSink(vp.output_.visibility);
  addDebugViewPasses(g, vp, tag, in);
}

std::string Renderer::addLightPasses(FrameGraph& g, Viewport& vp, const std::string& tag, const FrameInput& in) {
  const bool cameraMoved = view_ != vp.prev_.view || proj_ != vp.prev_.proj;
  layOutViewport(vp, in, cameraMoved);
  const std::string prelude = techniquePrelude(vp);

  PartContext part = partContext(vp, tag, in, cameraMoved, prelude);
  addShadowPass(g, vp, tag, vp.layout->addPasses(g, part), in);
  vp.layout->addPassesAfterShadow(g, part);
  // What the visibility tests read: the shadow map, or what the representation made of it.
  const std::string sm = vp.representation->addPasses(g, part);
  vp.shadowResource_ = sm;
  // Read back after the frame (tests, the reference's comparisons): the raw test too.
  if (keepGBuffer) g.requestSink("visibility.raw" + tag);
  // The accumulation adds the test, its own passes and the shading.
  const AccumulationContext ctx = accumulationContext(g, vp, tag, in, cameraMoved, prelude, sm, part.bindGBuffer);
  vp.output_ = vp.accumulation->addPasses(g, ctx);
  vp.layout->addPassesAfterShading(g, part, vp.output_);
  return prelude;
}

}  // namespace sl
