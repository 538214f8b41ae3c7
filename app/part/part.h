// A technique is a composition of three independent parts:
//   Layout         - where shadow-map texels go (uniform, focused, later PSM/LiSPSM/TSM/cascades)
//   Representation - what a texel stores and how visibility is reconstructed (depth + filter, ...)
//   Accumulation   - what happens in screen space over time (none, pixel-correct history)
// Each part is a C++ object plus a GLSL module, declares its parameters once, and knows nothing
// of the other two. A Preset names one combination with parameter overrides.
//
// This header is the part SDK (app/part/): what a layout, a representation or an accumulation may
// use. The renderer and every technique family depend on it; neither includes the other.
#pragma once

#include "core/params.h"
#include "part/contexts.h"
#include "part/light_space.h"
#include "part/shadow_draw_plan.h"
#include "scene/scene.h"

#include <epoxy/gl.h>
#include <glm/glm.hpp>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sl {

class FrameGraph;
class Framebuffer;

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
  // Adds passes after the shadow pass, reading this frame's map (ctx.shadowMap): the layout's
  // debug views of what was drawn.
  virtual void addPassesAfterShadow(FrameGraph& graph, const PartContext& ctx) {}
  // Adds passes after the shading, reading what the accumulation left (`shaded`: its visibility
  // and the depth the camera's surfaces were drawn with): a reduction whose result a later frame
  // uses can read this frame's depth instead of asking for a G-buffer.
  virtual void addPassesAfterShading(FrameGraph& graph, const PartContext& ctx, const AccumulationOutput& shaded) {}
  // How the shadow pass draws each light view's layer (one entry per view, whole layers by
  // default). A layout that rasterizes layers piecewise (paged virtual maps) asks for tiles;
  // `keepsLayers`: the representation keeps a layer's content when bound for tiles
  // (RepresentationState::keepsLayers), so tiles drawn in earlier frames are still there.
  // Called while the shadow pass runs, after this layout's own passes.
  virtual void planShadowLayers(std::vector<ShadowLayerDraw>& layers, bool keepsLayers) {}
  // False for a layout that draws its layers piecewise (pages): its views cannot be moved into
  // another layer's region (lights.one_atlas), as the tiles are placed by the layout alone.
  virtual bool drawsWholeViews() const { return true; }

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
  // Layouts with memory between frames or passes of their own return their own state.
  virtual std::unique_ptr<LayoutState> createState() const { return std::make_unique<LayoutState>(*this); }
};

struct Technique;

// What a representation shows in the V plot at one map texel: its visibility (or transmittance)
// at `samples` depths evenly over [0, 1], and the truth it is judged by, either a curve it
// computes itself (a pre-filtered map: the lit fraction of its filter box) or the world points on
// the texel's light ray at those depths, for the caller to trace (a deep map's transmittance).
struct VisibilityCurve {
  std::string axis;        // "receiver depth", "light depth"; empty: this representation has none
  std::string valueLabel;  // "visibility", "transmittance"
  std::vector<float> values;
  std::string truthLabel;
  std::vector<float> truth;         // or empty, and then
  std::vector<glm::vec3> truthRay;  // the points to trace, one per value
  bool empty() const { return axis.empty() || values.empty(); }
};

struct CurveQuery {
  ShaderLibrary* shaders = nullptr;
  const Technique* technique = nullptr;  // the state's own, with this frame's values
  const LightView* view = nullptr;       // the view the texel is in
  glm::vec3 uvLayer{0.0f};               // map uv and layer
  int samples = 256;
};

// One depth layer a viewport's lights share (lights.one_atlas): each light draws into its own
// region of it (LightView::atlasRect, placeInAtlasRegion) and reads only that region.
struct SharedDepthLayer {
  const Texture2D* depth = nullptr;          // GL_DEPTH_COMPONENT32F, an array of one layer
  const Framebuffer* framebuffer = nullptr;  // its layer as the depth attachment
  int size = 0;                              // texels per side
};

// Per-viewport state of a representation: owns the shadow-map targets (depth and what a texel
// stores, one layer per light view), may add passes after the shadow pass (blur, mip-maps,
// summed-area tables) and binds what its GLSL module samples.
class RepresentationState : public PartState {
 public:
  // Called every frame before prepare with the technique's current values: targets, formats
  // and defines may depend on them (storage format, filter method, number of terms).
  virtual void configure(const ParamSet& params) {}
  // Called every frame before configure: what the scene and the shadowed light call for (e.g.
  // semi-transparent casters, an area light) may decide the passes and defines.
  virtual void setScene(const Scene& scene, const Light& light) {}
  // Allocates (or keeps) the targets: size x size texels, `layers` layers, for `views` light
  // views (more than layers when views are packed into one layer, LightSpace::layerOf).
  virtual void prepare(int size, int layers, int views) = 0;
  // Binds one layer of the targets for the shadow pass and clears it.
  virtual void beginShadowLayer(int layer) = 0;
  // Binds a layer begun earlier in this shadow pass without clearing it: the next view packed
  // into the same layer draws beside the ones already there.
  virtual void continueShadowLayer(int layer) = 0;
  // True when a layer may be bound without clearing it for a layout that draws it piecewise
  // (bindShadowLayer), so tiles drawn in earlier frames are reused. Representations whose passes
  // read the whole layer keep the default: cleared every frame.
  virtual bool keepsLayers() const { return false; }
  virtual void bindShadowLayer(int layer) { beginShadowLayer(layer); }
  // Draws into `shared` instead of targets of its own from now on, when it can (a plain depth map
  // that nothing but the lookups reads): returns whether it will. Null: its own targets again.
  // While shared, the renderer clears only the light's region and never calls beginShadowLayer.
  virtual bool shareDepthLayer(const SharedDepthLayer* shared) { return false; }
  virtual bool canShareDepthLayer() const { return false; }
  // Adds passes after the shadow pass (reading ctx.shadowMap); returns the resource the
  // visibility and shading passes read.
  virtual std::string addPasses(FrameGraph& graph, const PartContext& ctx) { return ctx.shadowMap; }
  // Depth (or what stands for it) per layer, for the debug views.
  virtual const Texture2D* depthTexture() const = 0;
  // The V plot's curves at one texel of the last frame's map (none by default).
  virtual VisibilityCurve visibilityCurve(const CurveQuery& query) const { return {}; }
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
  // Its part of the shadow pass's plan: the fragment stage and which casters it draws.
  virtual CasterDraw casterDraw() const { return {}; }
  virtual std::unique_ptr<RepresentationState> createState() const = 0;
  // How far from the receiver's texel its lookups may read under `light`, in texels of the view
  // (a filter's radius, a blocker search's): a layout whose views end where another's begin (a
  // point light's faces) draws that far past each view's window, so the taps read that view's
  // own casters rather than a clamped edge or another view's square
  // (LayoutInput::filterReachTexels).
  virtual float filterReachTexels(const ParamSet& params, const Light& light) const { return 0.0f; }
};

// Per-viewport state of an accumulation (history buffers, adaptive exponents, frame counters).
// Its passes take the frame from the representation's output to the viewport's colour: the
// shadow test (its own pass, or ctx.addVisibilityTest), whatever it does over time, and the
// shading (ctx.addForwardShade, ctx.addDeferredShade, or a pass of its own that writes ctx.color).
// Adding passes has no side effects on the state: a pass that runs commits what it changes.
class AccumulationState : public PartState {
 public:
  // cameraMoved: the camera differs from the previous frame's.
  virtual LayoutJitter jitter(const ParamSet& params, bool cameraMoved) const { return {}; }
  // By default every frame stands alone: test and shading while the scene is rasterized.
  virtual AccumulationOutput addPasses(FrameGraph& graph, const AccumulationContext& ctx) {
    return ctx.addForwardShade();
  }
};

class Accumulation {
 public:
  virtual ~Accumulation() = default;
  virtual std::string id() const = 0;
  virtual std::string help() const = 0;
  virtual std::vector<ParamDecl> params() const { return {}; }
  virtual std::unique_ptr<AccumulationState> createState() const = 0;
};

// A named combination with parameter overrides, as a family declares it.
struct Preset {
  std::string id;
  std::string help;
  std::string layout;
  std::string representation;
  std::string accumulation;
  std::vector<std::string> overrides;  // "key=value"
};

// A resolved composition with its parameter values.
struct Technique {
  std::string presetId;
  const Layout* layout = nullptr;
  const Representation* representation = nullptr;
  const Accumulation* accumulation = nullptr;
  ParamSet params;            // common + layout + representation + accumulation declarations
  std::string label() const;  // "pcf (focused + depth-pcf)"
};

}  // namespace sl
