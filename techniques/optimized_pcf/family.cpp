// Optimized PCF (Castaño 2013): a tent-filtered depth test from a few bilinear hardware compares
// (shaders/representations/optimized_pcf.glsl). A family added through the part SDK alone: this
// file, its shader, its README and test, and one line in registry.cpp.
#include "part/depth_map_state.h"
#include "part/family.h"

namespace sl {

namespace {

constexpr const char* kEvaluate = "pcf.evaluate";

// The depth map with comparison sampling; the evaluation (taps or every texel) is a define.
class OptimizedPcfState : public DepthMapState {
 public:
  OptimizedPcfState() : DepthMapState(true) {}
  void configure(const ParamSet& params) override { texelByTexel_ = params.choice(kEvaluate) == "every-texel"; }
  std::string defines() const override { return texelByTexel_ ? "#define SL_TENT_TEXEL_BY_TEXEL\n" : ""; }

 private:
  bool texelByTexel_ = false;
};

class OptimizedPcf : public Representation {
 public:
  std::string id() const override { return "optimized-pcf"; }
  std::string help() const override {
    return "tent-filtered PCF from bilinear hardware compares (Castaño 2013): N = 3, 5, 7 in 4, 9, 16 taps";
  }
  std::string glslModule() const override { return "representations/optimized_pcf.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {{.key = "pcf.kernel",
             .type = ParamType::Int,
             .min = 3,
             .max = 7,
             .defaultValue = 5,
             .unit = "texels",
             .help = "tent filter of half-width (N + 1) / 2 texels; odd N = 3, 5, 7 take 4, 9, 16 bilinear taps"},
            {.key = kEvaluate,
             .type = ParamType::Enum,
             .defaultValue = 0,
             .help = "bilinear-taps: the optimized filter; every-texel: the same tent from (N + 1)² single-texel "
                     "compares, what the taps must reproduce",
             .choices = {"bilinear-taps", "every-texel"}}};
  }
  std::unique_ptr<RepresentationState> createState() const override { return std::make_unique<OptimizedPcfState>(); }
  // The tent weighs texels up to its half-width (N + 1) / 2 from the receiver: a point layout
  // draws each face that far past its window (an atlas widens its border to it).
  float filterReachTexels(const ParamSet& params, const Light&) const override {
    return params.has("pcf.kernel") ? 0.5f * float(params.i("pcf.kernel") + 1) : 0.0f;
  }
};

}  // namespace

Family optimizedPcfFamily() {
  Family f{.id = "optimized_pcf",
           .summary = "optimized PCF: a tent filter from a few bilinear shadow compares (Castaño 2013, The Witness)"};
  f.representations.push_back(std::make_unique<OptimizedPcf>());
  f.presets = {
      {"optimized-pcf",
       "focused shadow map, 5-texel tent PCF in 9 bilinear compare taps (Castaño 2013)",
       "focused",
       "optimized-pcf",
       "none",
       {}},
      {"pixel-correct-optimized-pcf",
       "pixel-correct with optimized tent PCF tests as f(n)",
       "focused",
       "optimized-pcf",
       "pixel-correct",
       {}},
  };
  return f;
}

}  // namespace sl
