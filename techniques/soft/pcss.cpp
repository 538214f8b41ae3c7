// PCSS (Fernando 2005) over any layout: the shadow map is a plain depth map (DepthMapState);
// the blocker search is a screen-space pass of its own over the G-buffer, `blocker-search[v]`,
// which writes per pixel the receiver-to-blocker distance and the penumbra radius (world units,
// so the same value serves every cascade); the visibility test reads it at its own pixel and
// filters with a rotated Poisson disk of that size in the view it tests. Without an area light
// (light.radius = 0) no search pass is added and the test is a minimum-kernel PCF.
#include "soft/pcss.h"
#include "part/part_view.h"
#include "part/penumbra_params.h"

#include "part/depth_map_state.h"
#include "gl/gl_util.h"
#include "gl/texture_units.h"
#include "part/frame_graph.h"
#include "scene/scene_effects.h"

#include <memory>

namespace sl {

namespace {

const char* kBlockerViewNames[] = {"blocker-depth", "penumbra"};

class PcssState : public DepthMapState {
 public:
  PcssState() : DepthMapState(false) {}

  std::string addPasses(FrameGraph& graph, const PartContext& ctx) override {
    const SceneEffects fx = ctx.scene ? sceneEffects(*ctx.scene, ctx.shadowedLight()) : SceneEffects{};
    areaLight_ = fx.areaLight;
    if (!areaLight_) {
      status_ = "pcss: point light (radius 0): no blocker search, minimum-kernel PCF";
      addViewPasses(graph, ctx, {});
      return ctx.shadowMap;
    }
    status_ = softLightStatus("pcss", fx, *ctx.params);
    ensureTarget(ctx.width, ctx.height);
    const std::string resource = "pcss.blocker" + ctx.viewportTag;
    // The pass includes the technique's modules; SL_PCSS_SEARCH_PASS keeps the representation
    // from sampling the target this pass writes.
    const std::string prelude = "#define SL_PCSS_SEARCH_PASS\n" + ctx.techniquePrelude;
    Framebuffer* fbo = &fbo_;
    graph.add({"blocker-search" + ctx.viewportTag, {"gbuffer", ctx.shadowMap}, {resource}, [ctx, prelude, fbo] {
                 ProgramSpec spec{"pcss blocker search",
                                  {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                                   {GL_FRAGMENT_SHADER, "representations/soft/blocker_search.frag"}},
                                  prelude};
                 Program& p = ctx.shaders->get(spec);
                 if (!p.valid()) return;
                 fbo->bind();
                 const float none[4] = {0, 0, 0, 0};
                 glClearNamedFramebufferfv(fbo->id(), GL_COLOR, 0, none);
                 p.use();
                 TextureUnits units;
                 ctx.bindTechnique(p, units);
                 ctx.bindGBuffer(p, units);
                 ctx.drawFullscreen();
               }});
    addViewPasses(graph, ctx, resource);
    return resource;
  }

  void bind(const Program& p, TextureUnits& units) const override {
    DepthMapState::bind(p, units);
    if (areaLight_ && blocker_) units.bind(p, "u_pcssBlocker", blocker_->id());
  }

  // Offered in every scene (a point light's show "not searched"): views are listed before the
  // first frame tells the state which kind of light it has.
  std::vector<std::string> views() const override { return {kBlockerViewNames[0], kBlockerViewNames[1]}; }
  std::string status() const override { return status_; }
  long long texels() const override {
    return DepthMapState::texels() + (blocker_ ? static_cast<long long>(blocker_->width()) * blocker_->height() : 0);
  }

 private:
  void ensureTarget(int w, int h) {
    if (blocker_ && blocker_->width() == w && blocker_->height() == h) return;
    // x: receiver-to-blocker distance along the light, y: penumbra radius (world units at the
    // receiver), z: 1 where the search found a blocker, w: search radius (texels of its view).
    blocker_ = std::make_unique<Texture2D>(GL_RGBA32F, w, h, "pcss.blocker");
    fbo_ = Framebuffer("pcss blocker search");
    fbo_.attach({blocker_.get()}, nullptr);
  }

  // blocker: the search's resource, "" when no search ran.
  void addViewPasses(FrameGraph& graph, const PartContext& ctx, const std::string& blocker) const {
    for (const char* name : kBlockerViewNames) {
      auto it = ctx.viewTargets.find(name);
      if (it == ctx.viewTargets.end() || !it->second) continue;
      Texture2D* target = it->second;
      const std::string resource = "view." + std::string(name) + ctx.viewportTag;
      const std::string defines = std::string(name) == "penumbra" ? "#define SL_VIEW_PENUMBRA\n" : "";
      // The G-buffer too: the radius is shown in texels of the view each pixel reads.
      std::vector<std::string> reads{"gbuffer"};
      if (!blocker.empty()) reads.push_back(blocker);
      graph.add({resource, reads, {resource}, [ctx, target, defines] {
                   drawPartView(ctx, target, "representations/soft/pcss_view.frag",
                                {.defines = defines, .withGBuffer = true});
                 }});
      graph.requestSink(resource);
    }
  }

  bool areaLight_ = false;
  std::string status_;
  std::unique_ptr<Texture2D> blocker_;
  Framebuffer fbo_;  // made with the target: states exist before a GL context does
};

class PcssRepresentation : public Representation {
 public:
  std::string id() const override { return "pcss"; }
  std::string help() const override {
    return "percentage-closer soft shadows (Fernando 2005): blocker search pass, penumbra from the light size "
           "and the blocker distance, rotated Poisson PCF of that size";
  }
  std::string glslModule() const override { return "representations/soft/pcss.glsl"; }
  std::vector<ParamDecl> params() const override {
    std::vector<ParamDecl> decls = penumbraParams();
    const std::vector<ParamDecl> own = {
        {.key = "pcss.blocker_samples",
         .type = ParamType::Int,
         .min = 4,
         .max = 64,
         .defaultValue = 16,
         .unit = "samples",
         .help = "Poisson taps of the blocker search (average depth of the texels closer than the receiver)"},
        {.key = "pcss.filter_samples",
         .type = ParamType::Int,
         .min = 4,
         .max = 64,
         .defaultValue = 32,
         .unit = "samples",
         .help = "Poisson depth tests of the variable-size PCF filter"},
        {.key = "pcss.rotate",
         .type = ParamType::Bool,
         .defaultValue = 1,
         .help = "rotate both Poisson disks per pixel (noise instead of banding)"},
    };
    decls.insert(decls.end(), own.begin(), own.end());
    return decls;
  }
  std::unique_ptr<RepresentationState> createState() const override { return std::make_unique<PcssState>(); }
  // Under an area light the blocker search and the filter both reach up to pcss.max_radius
  // texels; under a point of light the test is a PCF of kPcssMinRadius (1 texel).
  float filterReachTexels(const ParamSet& params, const Light& light) const override {
    if (!(light.radius > 0.0f)) return 1.0f;
    return params.has("pcss.max_radius") ? float(params.get("pcss.max_radius")) : 0.0f;
  }
};

}  // namespace

void registerSoftRepresentations(std::vector<std::unique_ptr<Representation>>& out) {
  out.push_back(std::make_unique<PcssRepresentation>());
}

void addSoftPresets(std::vector<Preset>& out) {
  // Receiver-plane bias: a large filter over a tilted receiver needs the plane's own depth at
  // each tap; slope bias scaled by the filter radius would lift the shadow off its contact.
  out.push_back({"pcss",
                 "percentage-closer soft shadows (Fernando 2005) on a focused map: blocker search pass, penumbra "
                 "from light.radius",
                 "focused",
                 "pcss",
                 "none",
                 {"bias.mode=receiver-plane"}});
  // Beyond every paper (the pixel-correct paper's future work): the pixel-correct history over
  // maps seen from a different point of the area light each frame converges to its visibility.
  // pc.reject off: a per-frame test in a penumbra disagrees with the mean by design.
  // Receiver-plane bias: slope-scaled bias, large where a sample of the disk grazes a receiver,
  // lifted Sponza's shadows off some receivers in every sample (fully lit pixels under casters:
  // rmse 0.0330 against 0.0147, techniques/soft/README.md).
  out.push_back({"pixel-correct-soft",
                 "pixel-correct history over maps from a jittered point of the area light (Halton over the disk): "
                 "converges to the area light's visibility at rest",
                 "focused",
                 "depth-nearest",
                 "pixel-correct",
                 {"pc.area_light=on", "pc.reject=1", "bias.mode=receiver-plane"}});
  out.push_back({"pcss-cascaded",
                 "PCSS over 4 cascades: search region and penumbra in each split's own texels",
                 "cascaded",
                 "pcss",
                 "none",
                 {"bias.mode=receiver-plane"}});
}

}  // namespace sl
