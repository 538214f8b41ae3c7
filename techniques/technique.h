// A technique is a composition of three independent parts:
//   Layout         - where shadow-map texels go (uniform, focused, later PSM/LiSPSM/TSM/cascades)
//   Representation - what a texel stores and how visibility is reconstructed (depth + filter, ...)
//   Accumulation   - what happens in screen space over time (none, pixel-correct history)
// Each part is a C++ object plus a GLSL module, declares its parameters once, and knows nothing
// of the other two. A Preset names one combination with parameter overrides.
#pragma once

#include "core/params.h"
#include "scene/scene.h"

#include <glm/glm.hpp>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace sl {

class FrameGraph;
class Layout;
class Program;
struct ProgramSpec;
class ShaderLibrary;
class Texture2D;
class TextureUnits;
struct AccumulationContext;

// Sub-texel change of the rasterization requested by an accumulation (pixel-correct jitter).
struct LayoutJitter {
  glm::vec2 offsetTexels{0.0f};
  float rotationRad = 0.0f;
  // A point of the area light's disk, in the unit disk (0 = its centre): layouts build the light
  // frame from the light moved there (layoutLight), so a history over frames integrates the
  // disk (pixel-correct-soft). No effect when light.radius is 0.
  glm::vec2 lightSample{0.0f};
};

// One light view: what one layer of the shadow map sees. Depth stored in the map is always the
// light-view linear depth mapped to [0,1] over [nearPlane, farPlane], whatever the projection,
// so biases mean the same thing in every layout.
struct LightView {
  glm::mat4 view{1.0f};
  glm::mat4 proj{1.0f};
  glm::mat4 viewProj{1.0f};
  bool perspective = false;
  float nearPlane = 0.1f;
  float farPlane = 100.0f;
  glm::vec2 windowMin{-1.0f}, windowMax{1.0f};  // orthographic window in light-view units
  // World size of one texel: orthographic = constant; perspective = this times view distance.
  float texelWorldSize = 0.01f;
  // Camera view depths this view serves (partitioned layouts pick a view per pixel by them) and
  // the width of the band, before splitFar, blended with the next view.
  float splitNear = 0.0f, splitFar = 1e30f, blendBand = 0.0f;
  // > 0: a logarithmic warp of the map's y after the projection (LogPSM, layouts/logpsm.h):
  // y in [-1, 1] -> 2 ln(1 + t/logDelta) / ln(1 + 1/logDelta) - 1 with t = (y + 1) / 2.
  float logDelta = 0.0f;
};

constexpr int kMaxLightViews = 8;

// What a layout computed for one frame: 1..kMaxLightViews views, one shadow-map layer each,
// all of `size` x `size` texels. The renderer uploads the views as one uniform block
// (shaders/common/light_views.glsl).
struct LightSpace {
  std::vector<LightView> views{LightView{}};
  int size = 1024;  // texels per side of every layer
  const LightView& primary() const { return views.front(); }
  bool perspective() const;  // any view perspective: stored depth is written per fragment
  static LightSpace single(const LightView& view, int size) { return LightSpace{{view}, size}; }
};

// What the visible pixels of an earlier frame covered (sample-distribution fitting, SDSM):
// camera view depth and position in the light's fixed basis (lightViewMatrix), min and max.
struct VisibleBounds {
  bool valid = false;
  float depthMin = 0, depthMax = 0;
  glm::vec3 lightMin{0.0f}, lightMax{0.0f};  // x, y and light-view distance
};

struct LayoutInput {
  const Scene* scene = nullptr;
  double time = 0.0;
  glm::mat4 cameraView{1.0f};
  glm::mat4 cameraProj{1.0f};
  const ParamSet* params = nullptr;
  LayoutJitter jitter;
  VisibleBounds visible;  // set by SdsmState when fit.sdsm is on and bounds have arrived
  // Unique per Renderer::setScene call over all renderers (0: unknown). What a layout derives
  // from the scene's geometry alone may be cached under it (a scene's address may be reused).
  uint64_t sceneGeneration = 0;
};

// What a part's per-viewport state sees when it adds its passes to a frame.
struct PartContext {
  std::string viewportTag;  // "[v]": unique per viewport, used in pass and resource names
  const Scene* scene = nullptr;
  double time = 0.0;
  ShaderLibrary* shaders = nullptr;
  const ParamSet* params = nullptr;
  const Layout* layout = nullptr;  // the technique's (its caster stages: casterStages in render/gpu_scene.h)
  const LightSpace* lightSpace = nullptr;
  glm::mat4 view{1.0f}, proj{1.0f};  // the camera
  int width = 0, height = 0;
  bool cameraMoved = false;
  int frameIndex = 0;
  std::string shadowMap;  // resource the shadow passes write (representation passes read it)
  // The visibility this viewport showed last frame (null before its first frame): what adaptive
  // criteria refine around (shadow edges). Read before this frame overwrites it.
  const Texture2D* previousVisibility = nullptr;
  // The representation's depth targets (depthTexture(), a 2D array; null before its first
  // frame). Read in a layout pass, before this frame's shadow pass: what the last frame drew.
  std::function<const Texture2D*()> shadowDepth;
  std::function<void()> drawFullscreen;
  // Sets the technique's uniforms and every part's bindings on a program that includes the
  // technique's modules (the technique prelude).
  std::function<void(const Program&, TextureUnits&)> bindTechnique;
  std::string techniquePrelude;  // a ProgramSpec prelude that includes the technique's modules
  // Binds the G-buffer (u_gPosition, u_gNormal, u_gAlbedo, u_gSurface; resource "gbuffer").
  std::function<void(const Program&, TextureUnits&)> bindGBuffer;
  // Debug views of this part shown this frame, and where to draw them (RGBA8, viewport size).
  std::map<std::string, Texture2D*> viewTargets;
  // Replaces this frame's light space after the layout's passes recomputed it (SDSM with no
  // readback latency); the number of views and their kind must stay the same.
  std::function<void(const LightSpace&)> replaceLightSpace;
  // Draws only the semi-transparent instances (scene_effects.h) at the frame's time with
  // programs built from `spec` (per material variant; `setup` runs once per program): no depth
  // test, no culling, into whatever framebuffer is bound (the deep shadow map's fragment lists).
  std::function<void(const ProgramSpec&, const std::function<void(const Program&, TextureUnits&)>&)>
      drawSemiTransparent;
  // Binds the scene's volumes (binding 6 of common/volume_density.glsl), uploaded when they
  // changed: one buffer per renderer, shared with the camera view's volumes pass.
  std::function<void()> bindVolumes;
};

// The one shape of per-viewport state of every part (layout, representation, accumulation):
// targets it owns, passes it adds to the frame graph (each subclass says where in the frame),
// bindings for its GLSL module, compile-time defines, debug views and a status line.
class PartState {
 public:
  virtual ~PartState() = default;
  virtual void reset() {}  // camera cut: forget everything from earlier frames
  // Defines placed in the technique prelude (before the modules are included).
  virtual std::string defines() const { return ""; }
  // Textures and uniforms of this part's GLSL module, on a program that includes it.
  virtual void bind(const Program& p, TextureUnits& units) const {}
  virtual std::vector<std::string> views() const { return {}; }  // debug views it can draw
  virtual std::string status() const { return ""; }
  virtual long long texels() const { return 0; }  // GPU texels of the targets it owns
};

class Layout;

// Per-viewport state of a layout: computes the light views; may add passes that run before the
// shadow pass (a depth reduction for sample-distribution fitting, page marking).
class LayoutState : public PartState {
 public:
  explicit LayoutState(const Layout& layout) : layout_(layout) {}
  virtual LightSpace compute(const LayoutInput& in);
  // Adds passes before the shadow pass; returns the resources the shadow pass must read.
  virtual std::vector<std::string> addPasses(FrameGraph& graph, const PartContext& ctx) { return {}; }
  // Layouts that rasterize a layer piecewise (paged virtual maps) keep the rest of the layer
  // between frames (drawsTiles). shadowTiles: the tiles of `layer` to draw this frame. `kept`:
  // the representation bound the layer without clearing it (RepresentationState::bindShadowLayer),
  // so tiles cached from earlier frames are still there.
  virtual bool drawsTiles() const { return false; }
  virtual int shadowTiles(int layer, bool kept) { return 0; }
  // Before tile `tile` is drawn into the bound layer: sets the viewport and clears the tile.
  virtual void beginShadowTile(int layer, int tile) {}
  // The tile's uniforms (its page-local projection) on each program that draws it.
  virtual void bindShadowTile(const Program& p, int layer, int tile) const {}
  // The clip transform the tile's draw uses after `layerViewProj` (its page of the layer), so
  // instances outside the tile can be skipped (shadowmap.cull_instances).
  virtual glm::mat4 shadowTileClip(int layer, int tile, const glm::mat4& layerViewProj) const { return layerViewProj; }

 protected:
  const Layout& layout_;
};

class Layout {
 public:
  virtual ~Layout() = default;
  virtual std::string id() const = 0;
  virtual std::string help() const = 0;
  virtual std::string glslModule() const = 0;  // under shaders/, included by every pass using it
  virtual std::vector<ParamDecl> params() const { return {}; }
  virtual LightSpace compute(const LayoutInput& in) const = 0;
  // True when casters must be drawn as patches (tessellation stages between shadow.vert and the
  // fragment shader): a warp that is not a projective map (LogPSM) bends straight edges.
  virtual bool tessellatesCasters() const { return false; }
  // Layouts with memory between frames or passes of their own return their own state.
  virtual std::unique_ptr<LayoutState> createState() const { return std::make_unique<LayoutState>(*this); }
};

// Per-viewport state of a representation: owns the shadow-map targets (depth and what a texel
// stores, one layer per light view), may add passes after the shadow pass (blur, mip-maps,
// summed-area tables) and binds what its GLSL module samples.
class RepresentationState : public PartState {
 public:
  // Called every frame before prepare with the technique's current values: targets, formats
  // and defines may depend on them (storage format, filter method, number of terms).
  virtual void configure(const ParamSet& params) {}
  // Called every frame before configure: what the scene calls for (e.g. semi-transparent
  // casters) may decide the passes and defines.
  virtual void setScene(const Scene& scene) {}
  // Allocates (or keeps) the targets: size x size texels, `layers` layers.
  virtual void prepare(int size, int layers) = 0;
  // Binds one layer of the targets for the shadow pass and clears it.
  virtual void beginShadowLayer(int layer) = 0;
  // Binds one layer for a layout that draws it piecewise; returns true when the layer's content
  // was kept (not cleared): then tiles drawn in earlier frames can be reused. By default the
  // layer is cleared as by beginShadowLayer (representations whose passes read the whole layer).
  virtual bool bindShadowLayer(int layer) {
    beginShadowLayer(layer);
    return false;
  }
  // Adds passes after the shadow pass (reading ctx.shadowMap); returns the resource the
  // visibility and shading passes read.
  virtual std::string addPasses(FrameGraph& graph, const PartContext& ctx) { return ctx.shadowMap; }
  // Depth (or what stands for it) per layer, for the debug views.
  virtual const Texture2D* depthTexture() const = 0;
};

class Representation {
 public:
  virtual ~Representation() = default;
  virtual std::string id() const = 0;
  virtual std::string help() const = 0;
  // Defines representationVisibility(vec3 uvLayer, float receiverDepth) and
  // representationFilterRadius().
  virtual std::string glslModule() const = 0;
  virtual std::vector<ParamDecl> params() const { return {}; }
  // Fragment shader of the shadow-map pass; moment representations write their own targets.
  virtual std::string shadowMapFragment() const { return "passes/shadow.frag"; }
  // True when the shadow pass must draw only opaque casters (the representation handles the
  // semi-transparent ones in passes of its own: deep shadow maps).
  virtual bool opaqueShadowPass() const { return false; }
  virtual std::unique_ptr<RepresentationState> createState() const = 0;
};

// Per-viewport state of an accumulation (history buffers, adaptive exponents, frame counters).
class AccumulationState : public PartState {
 public:
  // cameraMoved: the camera differs from the previous frame's.
  virtual LayoutJitter jitter(const ParamSet& params, bool cameraMoved) const { return {}; }
  // Adds passes that read ctx.rawVisibility and write ctx.finalVisibility; returns false when
  // the accumulation does nothing, in which case the raw visibility is used directly.
  virtual bool addPasses(FrameGraph& graph, AccumulationContext& ctx) { return false; }
  // False when the accumulation's own pass computes the shadow test (and writes the raw
  // visibility itself), so the renderer adds no separate visibility pass.
  virtual bool needsVisibilityPass() const { return true; }
};

class Accumulation {
 public:
  virtual ~Accumulation() = default;
  virtual std::string id() const = 0;
  virtual std::string help() const = 0;
  virtual std::vector<ParamDecl> params() const { return {}; }
  virtual std::unique_ptr<AccumulationState> createState() const = 0;
  // True when every frame stands alone (no passes), so the renderer may fuse the visibility
  // and shading passes.
  virtual bool passesThrough() const { return false; }
};

struct Preset {
  std::string id;
  std::string help;
  std::string layout;
  std::string representation;
  std::string accumulation;
  std::vector<std::string> overrides;  // "key=value"
};

// The registry of parts and presets (techniques/registry.cpp lists every family).
const std::vector<std::unique_ptr<Layout>>& allLayouts();
const std::vector<std::unique_ptr<Representation>>& allRepresentations();
const std::vector<std::unique_ptr<Accumulation>>& allAccumulations();
const std::vector<Preset>& allPresets();
const Layout* findLayout(const std::string& id);
const Representation* findRepresentation(const std::string& id);
const Accumulation* findAccumulation(const std::string& id);
const Preset* findPreset(const std::string& id);
// Parameters every technique has (shadow-map size, bias, culling, snapping).
const std::vector<ParamDecl>& commonParams();

// A resolved composition with its parameter values.
struct Technique {
  std::string presetId;
  const Layout* layout = nullptr;
  const Representation* representation = nullptr;
  const Accumulation* accumulation = nullptr;
  ParamSet params;            // common + layout + representation + accumulation declarations
  std::string label() const;  // "pcf (focused + depth-pcf)"
};

// The parameter that picks the composition's layout (every technique has it; commonParams).
inline constexpr const char* kLayoutParam = "technique.layout";

// Builds a technique from a preset id and applies "key=value" overrides; throws ParamError
// with a clear message for an unknown preset or a bad override. An override of
// technique.layout puts the preset's representation and accumulation over that layout (its
// parameters can be set in the same list).
Technique makeTechnique(const std::string& presetId, const std::vector<std::string>& overrides = {});
// After technique.layout was changed in place (a panel, a sweep): the technique rebuilt over that
// layout with every value the new one shares carried over; unchanged otherwise.
Technique recomposed(const Technique& t);

}  // namespace sl
