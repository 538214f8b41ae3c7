// What a part receives while it adds its passes to a viewport's frame: PartContext (every part)
// and AccumulationContext (an accumulation's screen-space inputs and outputs). The renderer fills
// them; a part sees the renderer through these alone.
#pragma once

#include "part/light_space.h"

#include <functional>
#include <map>
#include <string>

namespace sl {

class Layout;
class Program;
struct ProgramSpec;
class ShaderLibrary;
class Texture2D;
class TextureUnits;

// What a part's per-viewport state sees when it adds its passes to a frame.
struct PartContext {
  std::string viewportTag;  // "[v]": unique per viewport, used in pass and resource names
  const Scene* scene = nullptr;
  // The light this viewport's parts shadow: in a scene of several shadowed lights each gets its
  // own part states and passes (null: scene->light).
  const Light* light = nullptr;
  const Light& shadowedLight() const { return light ? *light : scene->light; }
  double time = 0.0;
  ShaderLibrary* shaders = nullptr;
  const ParamSet* params = nullptr;
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
  // Binds the scene's volumes (storage block SlVolumes of common/volume_density.glsl), uploaded when they
  // changed: one buffer per renderer, shared with the camera view's volumes pass.
  std::function<void()> bindVolumes;
};

// What an accumulation's passes leave for the renderer: the visibility shown and read back
// (R = visibility) and the depth the colour's surfaces were drawn with (what passes that
// composite over the colour read, e.g. participating media).
struct AccumulationOutput {
  std::string visibility;  // resource
  const Texture2D* visibilityTex = nullptr;
  std::string depth;  // resource that holds depthTex
  const Texture2D* depthTex = nullptr;
};

// Screen-space inputs an accumulation reads, the passes it may add and what it writes.
struct AccumulationContext {
  std::string viewportTag;      // unique per viewport, used in pass/resource names
  std::string rawVisibility;    // resource: RG16F (visibility, confidence)
  std::string finalVisibility;  // resource the accumulation must write: R channel = visibility
  const Texture2D* rawVisibilityTex = nullptr;
  Texture2D* finalVisibilityTex = nullptr;
  const Texture2D* gPosition = nullptr;  // RGBA32F world position, w = 1 where covered
  const Texture2D* gNormal = nullptr;    // RGBA32F world normal
  // RGBA32F: previous frame NDC xyz (per-object motion), w valid. Drawn only in frames where a
  // live pass declares resource "gbuffer.motion".
  const Texture2D* gMotion = nullptr;
  ShaderLibrary* shaders = nullptr;
  const ParamSet* params = nullptr;
  glm::mat4 view{1.0f}, proj{1.0f}, prevView{1.0f}, prevProj{1.0f};
  int width = 0, height = 0;
  bool cameraMoved = false;
  int frameIndex = 0;
  // Debug views requested on screen for this viewport, and where to draw them (RGBA8 targets).
  std::map<std::string, Texture2D*> viewTargets;
  // For accumulations that run the shadow test and the shading in their own pass, as the paper
  // does with multiple render targets: the technique's GLSL modules (a ProgramSpec prelude), a
  // binder for the G-buffer (u_gPosition, u_gNormal, u_gAlbedo, u_gSurface), every part's
  // bindings (shadow map, light views) and the technique's uniforms, and the colour target. Such
  // a pass writes rawVisibility itself.
  std::string techniquePrelude;
  std::function<void(const Program&, TextureUnits&)> bindTechniqueInputs;
  std::string shadowMap;  // resource
  std::string color;      // resource
  Texture2D* colorTex = nullptr;
  Texture2D* depthTex = nullptr;  // the viewport's own depth target for a scene pass
  // Draw the scene with programs built from `spec` (one per material variant; `setup` sets the
  // pass's uniforms on each, then u_viewProj, u_prevViewProj, u_prevView, per-instance
  // transforms and materials are set; depth test on) and the sky (colour attachment 0 only)
  // into the bound framebuffer.
  std::function<void(const ProgramSpec&, const std::function<void(const Program&, TextureUnits&)>&)> drawScene;
  std::function<void()> drawSky;
  Texture2D* rawVisibilityTarget = nullptr;  // writable when the accumulation computes the test
  // The renderer's shading passes, for an accumulation to add where it needs them (each returns
  // what it leaves for the renderer, or adds nothing but its pass):
  // - addForwardShade: the shadow test and the shading while the scene is rasterized into the
  //   viewport's own depth; writes `color` and `rawVisibility` (one pass, no G-buffer read).
  // - addVisibilityTest: the test over the G-buffer, a fullscreen pass writing `rawVisibility`.
  // - addDeferredShade: the shading of the G-buffer with a visibility resource and its texture.
  std::function<AccumulationOutput()> addForwardShade;
  std::function<void()> addVisibilityTest;
  std::function<AccumulationOutput(const std::string& visibility, const Texture2D* texture)> addDeferredShade;
};

}  // namespace sl
