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

#include <memory>
#include <string>
#include <vector>

namespace sl {

class FrameGraph;
struct AccumulationContext;

// Sub-texel change of the rasterization requested by an accumulation (pixel-correct jitter).
struct LayoutJitter {
  glm::vec2 offsetTexels{0.0f};
  float rotationRad = 0.0f;
};

// What a layout computed for one frame. Depth stored in the map is always the light-view
// linear depth mapped to [0,1] over [nearPlane, farPlane], whatever the projection, so biases
// mean the same thing in every layout.
struct LightSpace {
  glm::mat4 view{1.0f};
  glm::mat4 proj{1.0f};
  glm::mat4 viewProj{1.0f};
  bool perspective = false;
  float nearPlane = 0.1f;
  float farPlane = 100.0f;
  glm::vec2 windowMin{-1.0f}, windowMax{1.0f};  // orthographic window in light-view units
  int size = 1024;                              // texels per side
  // World size of one texel: orthographic = constant; perspective = this times view distance.
  float texelWorldSize = 0.01f;
};

struct LayoutInput {
  const Scene* scene = nullptr;
  double time = 0.0;
  glm::mat4 cameraView{1.0f};
  glm::mat4 cameraProj{1.0f};
  const ParamSet* params = nullptr;
  LayoutJitter jitter;
};

class Layout {
 public:
  virtual ~Layout() = default;
  virtual std::string id() const = 0;
  virtual std::string help() const = 0;
  virtual std::string glslModule() const = 0;  // under shaders/, included by every pass using it
  virtual std::vector<ParamDecl> params() const { return {}; }
  virtual LightSpace compute(const LayoutInput& in) const = 0;
};

class Representation {
 public:
  virtual ~Representation() = default;
  virtual std::string id() const = 0;
  virtual std::string help() const = 0;
  virtual std::string glslModule() const = 0;  // defines representationVisibility(...)
  virtual std::vector<ParamDecl> params() const { return {}; }
  // Depth texture sampled with hardware comparison (sampler2DShadow) instead of raw values.
  virtual bool compareSampler() const { return false; }
  // Fragment shader of the shadow-map pass; moment representations write their own targets.
  virtual std::string shadowMapFragment() const { return "passes/shadow.frag"; }
};

// Per-viewport state of an accumulation (history buffers, adaptive exponents, frame counters).
class AccumulationState {
 public:
  virtual ~AccumulationState() = default;
  // cameraMoved: the camera differs from the previous frame's.
  virtual LayoutJitter jitter(const ParamSet& params, bool cameraMoved) const { return {}; }
  virtual void reset() {}  // camera cut: forget everything from earlier frames
  // Adds passes that read ctx.rawVisibility and write ctx.finalVisibility; returns false when
  // the accumulation does nothing, in which case the raw visibility is used directly.
  virtual bool addPasses(FrameGraph& graph, AccumulationContext& ctx) { return false; }
  // False when the accumulation's own pass computes the shadow test (and writes the raw
  // visibility itself), so the renderer adds no separate visibility pass.
  virtual bool needsVisibilityPass() const { return true; }
  // Debug views this accumulation can draw (names), and the one-line status for the UI.
  virtual std::vector<std::string> views() const { return {}; }
  virtual std::string status() const { return ""; }
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

// Builds a technique from a preset id and applies "key=value" overrides; throws ParamError
// with a clear message for an unknown preset or a bad override.
Technique makeTechnique(const std::string& presetId, const std::vector<std::string>& overrides = {});

}  // namespace sl
