// One renderer for the explorer window, headless `render`, tests and benchmarks.
// Deferred: a G-buffer pass feeds every viewport's visibility pass, so techniques and the
// ray-traced reference shade exactly the same surface points.
#pragma once

#include "gl/gl_util.h"
#include "gl/pass_query_timer.h"
#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "part/frame_graph.h"
#include "part/part.h"
#include "part/transient_textures.h"
#include "render/light_budget.h"
#include "render/light_views_buffer.h"
#include "render/volumes_buffer.h"
#include "part/uniforms.h"

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sl {

struct GpuScene;

// Names of the debug views every technique offers; accumulations add their own.
const std::vector<std::string>& commonViewNames();

// The camera and scene time a frame was rendered with: what the next frame's motion, reprojection
// and "camera moved" are relative to.
struct PreviousFrame {
  glm::mat4 view{1.0f}, proj{1.0f};
  double time = 0.0;
  uint64_t epoch = 0;  // the renderer's scene/size generation it belongs to (0 = none yet)
};

// lights.one_atlas's shared layer (render/one_atlas.cpp), on the heap: the lights' states point
// at it (SharedDepthLayer) while the viewport that owns it may move.
struct OneAtlas {
  Texture2D depth;
  Framebuffer framebuffer;
  SharedDepthLayer layer;
};

// A viewport: one technique with its own state and targets, sharing the camera with the others.
// Its previous frame is its own too, so viewports rendered in separate calls (the bench renders
// entries in turn, A B A B ...) see the same history as when rendered alone.
class Viewport {
 public:
  explicit Viewport(Technique technique);
  Technique technique;
  // Per-viewport state of each part (one shape: targets, passes, bindings, defines, views).
  std::unique_ptr<LayoutState> layout;
  std::unique_ptr<RepresentationState> representation;
  std::unique_ptr<AccumulationState> accumulation;
  std::vector<std::string> shownViews;  // debug views to draw this frame (others are culled)
  LightSpace lightSpace;                // of the last frame
  // Outputs of the last frame (owned by the renderer's per-viewport targets).
  const Texture2D* colorTexture() const { return color_.get(); }
  // The visibility the shade pass used (after accumulation, if any): R = visibility.
  const Texture2D* visibilityTexture() const {
    return output_.visibilityTex ? output_.visibilityTex : rawVisibility_.get();
  }
  const Texture2D* rawVisibilityTexture() const { return rawVisibility_.get(); }
  const Texture2D* viewTexture(const std::string& name) const;
  std::vector<std::string> availableViews() const;
  // GPU texels the parts' targets hold (shadow map, page tables, moments, histories): the
  // memory side of a technique's cost, `shadow_texels` in `render --stats` and the bench.
  long long shadowTexels() const;
  // The debug views shown this frame (shownViews that exist) and the targets they are drawn into.
  std::map<std::string, Texture2D*> shownViewTargets();
  // The parts' status lines joined ("" when none has one), and in a scene of several lights how
  // many were shadowed.
  std::string status() const;
  // In a scene of several shadowed lights (Scene::otherLights): the visibility this viewport's
  // technique computed for the k-th of them (null for an unshadowed light or before a frame).
  // visibilityTexture() is Scene::light's; the colour sums every light.
  const Texture2D* otherLightVisibility(size_t k) const;
  void setTechnique(Technique t);  // keeps targets, resets history

 private:
  std::string oneAtlasStatus() const;  // status()'s words on lights.one_atlas's shared layer
  friend class Renderer;
  std::unique_ptr<Texture2D> rawVisibility_, finalVisibility_, color_, depth_;
  std::map<std::string, std::unique_ptr<Texture2D>> views_;
  Framebuffer visibilityFbo_, colorFbo_, forwardFbo_;
  std::unique_ptr<LightViewsBuffer> lightViews_;
  int targetsW_ = 0, targetsH_ = 0;
  std::string shadowResource_;    // what the visibility tests read (the representation's output)
  AccumulationOutput output_;     // what the accumulation's passes left: the shown visibility, the colour's depth
  PreviousFrame prev_;            // this viewport's last frame
  int frameIndex_ = 0;            // frames this viewport has rendered
  bool visibilityHeld_ = false;   // its visibility texture holds a finished frame of this size
  const Light* light_ = nullptr;  // the light its parts shadow this frame (a scene light)
  // This frame's values for the parts: technique.params with the map size the texel budget gave
  // this light (render/light_budget.h; mapSize_ 0 = the technique's own shadowmap.size).
  ParamSet frameParams_;
  int mapSize_ = 0;
  bool drawn_ = true;  // an other light: false when no visible point is in its reach
  // An other light of limited reach: the pixels its range can light (x, y, width, height); its
  // visibility test and direct term run there only (the rest is beyond its range: unlit).
  // Width 0: the whole frame.
  glm::ivec4 scissor_{0};
  double heldFootprint_ = 0.0;  // what the texel budget last gave this light (light_budget.h)
  bool laidOut_ = false;        // lightSpace is its technique's layout's (not a default, nor a former technique's)
  // lights.one_atlas (render/one_atlas.cpp): this light's region of the shared layer this frame
  // (width 0: none; its own maps), the layer, whether this frame's views were placed there, and
  // where they were placed last (a move redraws the light: its layout is reset).
  glm::ivec4 atlasRegion_{0};
  const SharedDepthLayer* oneAtlasLayer_ = nullptr;
  bool inOneAtlas_ = false;
  glm::ivec4 placedRegion_{0};
  int placedAtlasSide_ = 0;
  // The user's viewport: the shared layer itself.
  std::unique_ptr<OneAtlas> oneAtlas_;
  double budgetTexels_ = 0.0;  // the user's viewport: texels the budget gave its lights this frame
  int sizeRange_[2] = {0, 0};  // and their smallest and largest map size
  // Scene::otherLights' shadowed entries: the same technique with its own part states and
  // targets, one viewport per light (null for an unshadowed one). See render/other_lights.cpp.
  std::vector<std::unique_ptr<Viewport>> otherLights_;
  std::unique_ptr<Texture2D> otherDirect_;  // the other lights' direct light summed (RGBA16F)
  Framebuffer otherDirectFbo_;
};

struct FrameInput {
  Camera camera;
  double time = 0.0;
  int width = 640, height = 360;
  bool cut = false;  // camera jumped or scene changed: accumulations forget their history
  // The camera the layouts fit their light views to (and pick them by), when not `camera`: bench
  // shades one fixed view with maps fitted to a moving camera, so that what changes at a fixed
  // world point is the map alone (world-space flicker).
  std::optional<Camera> fitCamera;
};

struct FrameStats {
  std::vector<PassTiming> passes;  // passes that ran, in order, with their time
  double frameMs = 0;
  std::string timer;  // "cpu-fence" (glFinish + steady clock) or "gpu-query"
};

class Renderer {
 public:
  explicit Renderer(ShaderLibrary& shaders);
  ShaderLibrary& shaders() const { return shaders_; }
  ~Renderer();
  void setScene(const Scene& scene);  // uploads; throws std::runtime_error on GL failure
  const Scene* scene() const { return scene_; }
  void render(const FrameInput& in, const std::vector<Viewport*>& viewports);
  const FrameStats& stats() const { return stats_; }
  // The frame graph's transient targets kept for later frames (blur scratch targets, ...).
  const TransientTextures& transientTextures() const { return transients_; }
  bool timePasses = true;  // bracket passes with a timer (cheap on GPU, glFinish on llvmpipe)
  // On a GPU (timer queries): wait at the end of each frame for its own pass times (the bench,
  // the command line, tests), or show the newest frame's that have arrived, a frame or two old,
  // without making the CPU wait for the frame it queued (the explorer).
  bool waitForPassTimes = true;
  // Timer queries even on a software renderer, whose queries do not measure the work (tests of
  // the query path).
  bool forceTimerQueries = false;
  // Render the G-buffer even when no pass of the frame reads it, for readback (reference,
  // metrics, tests). Techniques shade forward, so the explorer turns this off while moving.
  bool keepGBuffer = true;
  bool hasFreshGBuffer() const { return gbufferFresh_; }  // the last frame drew the G-buffer
  // The caster triangles the last sorted shadow draw (logpsm.sort_casters) drew plain and as
  // patches, over its instances; read back from the GPU (for tests and measurements, not frames).
  glm::ivec2 sortedCasterTriangles() const;
  // Check every frame's wiring before it runs (FrameGraph::compile: a pass reading what no
  // earlier pass writes, two passes of one name); a mistake throws std::logic_error. On in debug
  // builds and in every GL test (tests/gl_test_util.h), or with SHADOWLAB_VALIDATE_GRAPH=1.
  bool validateFrameGraph = defaultValidateFrameGraph();
  static bool defaultValidateFrameGraph();

  // G-buffer of the last frame, for the reference tracer and metrics.
  const Texture2D& gPosition() const { return *gPosition_; }
  const Texture2D& gNormal() const { return *gNormal_; }
  // RGBA32UI: instance index + 1 (0 = background), triangle index in its mesh, packed facet
  // normal (shaders/common/facet.glsl), 0.
  const Texture2D& gSurface() const { return *gSurface_; }

  // The frame `in` shaded by the deferred shade pass (passes/shade.frag, common/shading.glsl)
  // with `visibility` (one float per pixel, rows bottom-up like every readback) in place of a
  // technique's: what a technique's colour would be with that visibility, e.g. the reference's
  // (image_wrong_pct). Draws `in`'s G-buffer unless it holds that frame already; `in` must have
  // the size of the last rendered frame. Viewports' histories are not touched. RGBA8, bottom-up.
  // Empty when the shade program does not build (the shader library has the error); throws
  // std::invalid_argument on a size mismatch.
  // In a scene of several lights, `others` holds one visibility per Scene::otherLights entry
  // (ignored, and may be empty, for an unshadowed one) and the colour sums every light, as the
  // viewports' does; a missing entry throws std::invalid_argument.
  std::vector<unsigned char> shadeWithVisibility(const FrameInput& in, const std::vector<float>& visibility,
                                                 const std::vector<std::vector<float>>& others = {});

 private:
  void ensureTargets(int w, int h);
  void ensureViewportTargets(Viewport& vp, int w, int h);
  void addViewportPasses(FrameGraph& g, Viewport& vp, size_t index, const FrameInput& in);
  // One light's passes of a viewport (layout, shadow, representation, accumulation); the name of
  // the technique prelude they were built with.
  std::string addLightPasses(FrameGraph& g, Viewport& vp, const std::string& tag, const FrameInput& in);
  // Scene::otherLights (render/other_lights.cpp): each shadowed one's passes, their direct light
  // summed, and the colour shaded with every light. Nothing when the scene has one light.
  void addOtherLightsPasses(FrameGraph& g, Viewport& vp, const std::string& tag, const FrameInput& in);
  void syncOtherLightViewports(Viewport& vp);
  // Which other lights this frame draws and every light's map size (render/light_budget.h).
  void budgetLightMaps(Viewport& vp, const FrameInput& in);
  // lights.one_atlas: a region of one shared depth layer for each drawn light of one layer whose
  // layout and representation can draw there (canJoinOneAtlas; the others keep maps of their own).
  // asked: the map size of each light in the shared layer (0: not in it; 0 everywhere: no layer).
  bool canJoinOneAtlas(const Viewport& light, const LightDemand& demand) const;
  void assignOneAtlas(Viewport& vp, const std::vector<Viewport*>& lights, const std::vector<int>& asked);
  // After a light's layout computed its views: moved into its region when it has one.
  void placeInOneAtlas(Viewport& light);
  int lightLayerCount(Viewport& light, const FrameInput& in);
  LayoutInput layoutInput(Viewport& vp, const FrameInput& in);
  void ensureOtherDirectTarget(Viewport& vp, int w, int h);
  // The colour with Scene::light's `visibility` plus the other lights' summed direct light.
  bool shadeLights(const Framebuffer& target, const Texture2D& visibility, const Texture2D& otherDirect);
  const Texture2D& substitutedOtherDirect(int w, int h, const std::vector<std::vector<float>>& others);
  const Light& lightOf(const Viewport& vp) const { return vp.light_ ? *vp.light_ : scene_->light; }
  void layOutViewport(Viewport& vp, const FrameInput& in, bool cameraMoved);
  void executeTimed(const FrameGraph& graph);
  // The shading passes an accumulation adds through its context (render/shading_passes.cpp).
  // bindInputs: the G-buffer and every part's bindings on a visibility-computing program.
  AccumulationOutput addForwardShadePass(FrameGraph& g, Viewport& vp, const std::string& tag,
                                         const std::string& prelude, const std::string& shadowMap,
                                         const ProgramSetup& bindInputs, const FrameInput& in);
  void addVisibilityPass(FrameGraph& g, Viewport& vp, const std::string& tag, const std::string& prelude,
                         const std::string& shadowMap, const ProgramSetup& bindInputs);
  AccumulationOutput addDeferredShadePass(FrameGraph& g, Viewport& vp, const std::string& tag,
                                          const std::string& visibility, const Texture2D* visibilityTex);
  void addDebugViewPasses(FrameGraph& g, Viewport& vp, const std::string& tag, const FrameInput& in);
  void drawLightSpaceOverview(const Viewport& vp, Texture2D& target, Texture2D& depth, const FrameInput& in);
  // Scenes with volumes: marches them over the viewport's colour (render/volume_pass.cpp).
  // depth: the target the colour's surfaces were drawn with; reads: what the lookup needs.
  void addVolumesPass(FrameGraph& g, Viewport& vp, const std::string& tag, const std::string& prelude,
                      const Texture2D* depth, const std::vector<std::string>& reads);
  std::string techniquePrelude(const Viewport& vp) const;
  // The technique's uniforms and every part's bindings (light views, shadow map, ...).
  void bindTechnique(const Program& p, TextureUnits& units, const Viewport& vp) const;
  PartContext partContext(Viewport& vp, const std::string& tag, const FrameInput& in, bool cameraMoved,
                          const std::string& prelude);
  AccumulationContext accumulationContext(FrameGraph& g, Viewport& vp, const std::string& tag, const FrameInput& in,
                                          bool cameraMoved, const std::string& prelude, const std::string& shadowMap,
                                          const ProgramSetup& bindGBuffer);
  void addShadowPass(FrameGraph& g, Viewport& vp, const std::string& tag, const std::vector<std::string>& reads,
                     const FrameInput& in);
  ShadowDrawPlan shadowDrawPlan(Viewport& vp) const;
  void bindShadowLayerFor(Viewport& vp, const ShadowDrawPlan& plan, int view, std::vector<bool>& begun);
  void drawShadowLayer(Viewport& vp, const ShadowDrawPlan& plan, const ProgramSpec& spec, int view,
                       std::vector<bool>& begun, double time);
  void drawFullscreen();
  // positionsOnly: only the world-position target (and depth) is written, the others keep what
  // they held; for frames whose passes read positions alone (resource "gbuffer.position").
  // withMotion: the fifth target, each pixel's previous-frame position ("gbuffer.motion").
  void drawGBuffer(const glm::mat4& viewProj, double time, const PreviousFrame& prev, bool positionsOnly = false,
                   bool withMotion = false);
  std::string shadePrelude() const;  // defines of the deferred shade pass
  // u_gPosition, u_gNormal, u_gAlbedo, u_gSurface; and with a visibility (u_visibility).
  void bindGBuffer(const Program& p, TextureUnits& units) const;
  void bindGBuffer(const Program& p, TextureUnits& units, const Texture2D* visibility) const;
  void drawSky();
  // prev: the frame motion and reprojection are relative to (the viewport's own).
  void drawSceneForward(const ProgramSpec& spec, const ProgramSetup& setup, double time, const PreviousFrame& prev);

  ShaderLibrary& shaders_;
  const Scene* scene_ = nullptr;
  std::unique_ptr<GpuScene> gpu_;
  std::unique_ptr<Texture2D> gPosition_, gNormal_, gAlbedo_, gSurface_, gMotion_, gDepth_;
  Framebuffer gFbo_, gFboMotion_;  // without and with the motion target
  bool gbufferFresh_ = false;      // this frame's G-buffer pass wrote every target
  int width_ = 0, height_ = 0;
  GLuint emptyVao_ = 0, linesVao_ = 0, linesVbo_ = 0;
  // Bumped by setScene and by a resize: every previous frame of an older epoch is a cut.
  uint64_t epoch_ = 1;
  uint64_t sceneGeneration_ = 0;  // LayoutInput::sceneGeneration of the current scene
  PreviousFrame prev_;            // of the last render call: the shared G-buffer's motion is relative to it
  struct GBufferContent {
    glm::mat4 viewProj{1.0f};
    double time = 0.0;
    uint64_t epoch = 0;  // 0: nothing drawn
  } gbufferHolds_;       // what the G-buffer targets hold now
  // shadeWithVisibility's own targets: the substituted visibility and the colour it gives.
  std::unique_ptr<Texture2D> substVisibility_, substColor_;
  Framebuffer substFbo_;
  std::vector<std::unique_ptr<Texture2D>> substOtherVisibility_;  // one per Scene::otherLights entry
  std::unique_ptr<Texture2D> substOtherDirect_;
  Framebuffer substOtherDirectFbo_;
  // Scene::volumes on the GPU, for the volumes pass and the parts (PartContext::bindVolumes).
  std::unique_ptr<VolumesBuffer> volumes_;
  TransientTextures transients_;                // the frame graph's transient targets, kept between frames
  std::unique_ptr<PassQueryTimer> queryTimer_;  // the passes' timer queries (on a GPU)
  void bindVolumes();
  FrameStats stats_;
  glm::mat4 view_{1.0f}, proj_{1.0f};
};

}  // namespace sl
