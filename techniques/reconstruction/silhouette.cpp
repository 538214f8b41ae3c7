// Shadow silhouette maps (Sen, Cammarano and Hanrahan 2003) as a representation.
#include "reconstruction/reconstruction.h"
#include "reconstruction/silhouette_state.h"

namespace sl {

namespace {

class SilhouetteRepresentation : public Representation {
 public:
  std::string id() const override { return "silhouette"; }
  std::string help() const override {
    return "depth map + silhouette map (Sen et al. 2003): one silhouette-edge point per texel; the shadow edge is "
           "rebuilt piecewise linearly from the four neighbours' points (quadrant test)";
  }
  std::string glslModule() const override { return "representations/silhouette.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {{.key = "silhouette.hidden_bias",
             .type = ParamType::Float,
             .min = 0,
             .max = 0.2,
             .defaultValue = 0.01,
             .unit = "depth [0,1]",
             .help = "an edge point farther from the light than all four depth samples of its texel by more than "
                     "this is hidden behind another caster and not stored"},
            {.key = "silhouette.reconstruct",
             .type = ParamType::Bool,
             .defaultValue = 1,
             .help = "use the silhouette points where the four depth tests disagree (off: nearest depth test, "
                     "the same map as standard)"}};
  }
  std::unique_ptr<RepresentationState> createState() const override { return std::make_unique<SilhouetteMapState>(); }
};

}  // namespace

void registerReconstructionRepresentations(std::vector<std::unique_ptr<Representation>>& out) {
  out.push_back(std::make_unique<SilhouetteRepresentation>());
}

void addReconstructionPresets(std::vector<Preset>& out) {
  out.push_back({"silhouette",
                 "shadow silhouette map (Sen et al. 2003): focused depth map + silhouette points, piecewise-linear "
                 "shadow edges",
                 "focused",
                 "silhouette",
                 "none",
                 {}});
  out.push_back({"forward",
                 "forward shadow mapping (Zhang 1998): every light-view sample splatted into the eye view; pixels no "
                 "splat reaches stay dark (holes)",
                 "focused",
                 "depth-nearest",
                 "forward",
                 {}});
}

}  // namespace sl
