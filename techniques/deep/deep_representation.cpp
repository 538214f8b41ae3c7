#include "deep/deep_representation.h"

#include "deep/deep_state.h"

namespace sl {

namespace {

class DeepRepresentation : public Representation {
 public:
  std::string id() const override { return "deep"; }
  std::string help() const override {
    return "deep shadow map (Lokovic & Veach 2000): per texel a piecewise-linear transmittance function of depth "
           "for semi-transparent casters (hair, glTF BLEND, volumes) times a nearest depth test for opaque ones";
  }
  std::string glslModule() const override { return "representations/deep.glsl"; }
  // The semi-transparent casters go into the fragment lists (DeepState), not the opaque map.
  CasterDraw casterDraw() const override { return {"passes/shadow.frag", CasterSet::Opaque}; }
  std::vector<ParamDecl> params() const override {
    return {
        {.key = "deep.nodes",
         .type = ParamType::Int,
         .min = 2,
         .max = 32,
         .defaultValue = 8,
         .unit = "nodes",
         .help = "nodes (depth, transmittance) per texel of the compressed function; the tolerance grows where a "
                 "texel needs more"},
        {.key = "deep.tolerance",
         .type = ParamType::Float,
         .min = 0,
         .max = 0.5,
         .defaultValue = 0.02,
         .unit = "transmittance",
         .help = "largest error of the piecewise-linear compression (Lokovic & Veach's error bound)"},
        {.key = "deep.size",
         .type = ParamType::Int,
         .min = 64,
         .max = 2048,
         .defaultValue = 512,
         .unit = "texels",
         .help = "deep map texels per side (the opaque depth map keeps shadowmap.size)",
         .logScale = true},
        {.key = "deep.samples",
         .type = ParamType::Int,
         .min = 1,
         .max = 16,
         .defaultValue = 1,
         .unit = "samples",
         .help = "light-image samples per deep texel (1, 2, 4, 8 or 16); each sample keeps its own transmittance "
                 "and a texel stores their average, so strands thinner than a texel count by their coverage",
         .logScale = true},
        {.key = "deep.fragments",
         .type = ParamType::Int,
         .min = 4,
         .max = 64,
         .defaultValue = 32,
         .unit = "fragments",
         .help = "semi-transparent fragments stored per texel before compression; more are dropped and reported "
                 "in the status"},
        {.key = "deep.volume_steps",
         .type = ParamType::Int,
         .min = 4,
         .max = 256,
         .defaultValue = 48,
         .unit = "steps",
         .help = "ray-march steps through the volumes along each texel's light ray"},
    };
  }
  std::unique_ptr<RepresentationState> createState() const override { return std::make_unique<DeepState>(); }
};

}  // namespace

void registerDeepRepresentations(std::vector<std::unique_ptr<Representation>>& out) {
  out.push_back(std::make_unique<DeepRepresentation>());
}

void addDeepPresets(std::vector<Preset>& presets) {
  presets.push_back(
      {"deep",
       "deep shadow map (Lokovic & Veach 2000) for hair and smoke, nearest depth test for opaque casters; "
       "in a scene without semi-transparent casters exactly standard",
       "focused",
       "deep",
       "none",
       {}});
}

}  // namespace sl
