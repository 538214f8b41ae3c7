// Depth representations: the shadow map stores one depth per texel; they differ only in how
// visibility is reconstructed from it (survey: "shadow map as signal reconstruction").
#include "depth/depth_representations.h"

#include "part/depth_map_state.h"

namespace sl {

namespace {

class DepthRepresentation : public Representation {
 public:
  using Reach = float (*)(const ParamSet&);
  DepthRepresentation(std::string id, std::string help, std::string module, std::vector<ParamDecl> params, bool compare,
                      Reach reach = nullptr)
      : id_(std::move(id)),
        help_(std::move(help)),
        module_(std::move(module)),
        params_(std::move(params)),
        compare_(compare),
        reach_(reach) {}
  std::string id() const override { return id_; }
  std::string help() const override { return help_; }
  std::string glslModule() const override { return module_; }
  std::vector<ParamDecl> params() const override { return params_; }
  std::unique_ptr<RepresentationState> createState() const override {
    return std::make_unique<DepthMapState>(compare_, /*shareable=*/true);
  }
  float filterReachTexels(const ParamSet& params, const Light&) const override {
    return reach_ ? reach_(params) : 0.0f;
  }

 private:
  std::string id_, help_, module_;
  std::vector<ParamDecl> params_;
  bool compare_;
  Reach reach_;
};

}  // namespace

void registerDepthRepresentations(std::vector<std::unique_ptr<Representation>>& out) {
  out.push_back(std::make_unique<DepthRepresentation>(
      "depth-nearest", "one depth test at the nearest texel (Williams 1978): hard, blocky edges",
      "representations/depth_nearest.glsl", std::vector<ParamDecl>{}, false));
  out.push_back(std::make_unique<DepthRepresentation>(
      "depth-bilinear", "hardware 2x2 depth compare with bilinear weights of the results (sampler2DShadow)",
      "representations/depth_bilinear.glsl", std::vector<ParamDecl>{}, true));
  out.push_back(std::make_unique<DepthRepresentation>(
      "depth-pcf", "percentage-closer filtering over an NxN box of texels (Reeves et al. 1987)",
      "representations/depth_pcf.glsl",
      std::vector<ParamDecl>{{.key = "pcf.kernel",
                              .type = ParamType::Int,
                              .min = 2,
                              .max = 9,
                              .defaultValue = 3,
                              .unit = "texels",
                              .help = "box filter width N: N x N depth tests are averaged"}},
      false, [](const ParamSet& p) { return p.has("pcf.kernel") ? 0.5f * float(p.i("pcf.kernel")) : 0.0f; }));
  out.push_back(std::make_unique<DepthRepresentation>(
      "depth-poisson", "PCF over a Poisson disk, rotated per pixel to trade banding for noise (Reeves et al. 1987)",
      "representations/depth_poisson.glsl",
      std::vector<ParamDecl>{{.key = "poisson.samples",
                              .type = ParamType::Int,
                              .min = 4,
                              .max = 32,
                              .defaultValue = 16,
                              .unit = "samples",
                              .help = "number of Poisson-disk depth tests"},
                             {.key = "poisson.radius",
                              .type = ParamType::Float,
                              .min = 0.5,
                              .max = 8,
                              .defaultValue = 1.5,
                              .unit = "texels",
                              .help = "disk radius"},
                             {.key = "poisson.rotate",
                              .type = ParamType::Bool,
                              .defaultValue = 1,
                              .help = "rotate the disk per pixel (noise instead of banding)"}},
      false, [](const ParamSet& p) { return p.has("poisson.radius") ? float(p.get("poisson.radius")) : 0.0f; }));
}

}  // namespace sl
