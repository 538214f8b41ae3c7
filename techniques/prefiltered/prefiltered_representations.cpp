// Pre-filtered representations: the shadow map stores moments of the depth distribution that
// can be filtered like colour, and each representation reconstructs visibility from them.
// Each is a MomentSpec (what is stored) + a GLSL module under
// shaders/representations/prefiltered/ (how it is reconstructed).
#include "prefiltered/prefiltered_representations.h"

#include "prefiltered/moment_spec.h"
#include "prefiltered/moment_state.h"
#include "part/penumbra_params.h"

#include <cmath>

namespace sl {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kConvolutionSpan = 0.9;  // shaders/representations/prefiltered/convolution.glsl

class PrefilteredRepresentation : public Representation {
 public:
  PrefilteredRepresentation(std::string id, std::string help, std::string module, std::vector<ParamDecl> own,
                            MomentSpec spec)
      : id_(std::move(id)), help_(std::move(help)), module_(std::move(module)), spec_(std::move(spec)) {
    if (!spec_.soft()) {
      params_ = filterParams(!spec_.logFilter);
    } else {
      params_ = softFilterParams();
      const std::vector<ParamDecl> penumbra = penumbraParams();
      params_.insert(params_.end(), penumbra.begin(), penumbra.end());
    }
    params_.insert(params_.end(), own.begin(), own.end());
  }
  std::string id() const override { return id_; }
  std::string help() const override { return help_; }
  std::string glslModule() const override { return module_; }
  std::vector<ParamDecl> params() const override { return params_; }
  std::unique_ptr<RepresentationState> createState() const override {
    return std::make_unique<MomentMapState>(spec_, module_);
  }

 private:
  std::string id_, help_, module_;
  std::vector<ParamDecl> params_;
  MomentSpec spec_;
};

ParamDecl minVariance(const std::string& key, double value) {
  return {.key = key,
          .type = ParamType::Float,
          .min = 0,
          .max = 0.01,
          .defaultValue = value,
          .unit = "depth^2",
          .help =
              "variance floor: a flat occluder filling the kernel still gets this spread (against acne and "
              "the 16-bit cancellation of z^2 - z*z)",
          .logScale = true};
}

ParamDecl bleed(const std::string& key) {
  return {.key = key,
          .type = ParamType::Float,
          .min = 0,
          .max = 0.95,
          .defaultValue = 0,
          .help = "light-bleeding reduction: bounds below this become shadow, the rest is rescaled (linstep)"};
}

std::string warpDefine(const ParamSet& p) {
  return "#define SL_WARP_MAX_EXPONENT " + std::to_string(maxWarpExponent(formatBits(p))) + "\n";
}

// The exponent the GLSL uses: clamped to what the storage format holds.
double warpExponent(const ParamSet& p, const std::string& key) {
  return std::clamp(p.get(key), 0.01, static_cast<double>(maxWarpExponent(formatBits(p))));
}

MomentSpec twoMoments() {
  return {.channels = [](const ParamSet&) { return 2; },
          .clearValue =
              [](const ParamSet&) {
                return std::vector<float>{1.0f, 1.0f};
              },
          .hasVariance = true};
}

MomentSpec evsmSpec() {
  MomentSpec s;
  s.channels = [](const ParamSet& p) { return p.i("evsm.warps") == 0 ? 2 : 4; };
  s.clearValue = [](const ParamSet& p) {
    const double cp = warpExponent(p, "evsm.exponent_pos"), cn = warpExponent(p, "evsm.exponent_neg");
    return std::vector<float>{float(std::exp(cp)), float(std::exp(2 * cp)), float(-std::exp(-cn)),
                              float(std::exp(-2 * cn))};
  };
  s.defines = [](const ParamSet& p) { return warpDefine(p) + (p.i("evsm.warps") == 1 ? "#define SL_EVSM4\n" : ""); };
  s.hasVariance = true;
  return s;
}

MomentSpec ewgfSpec() {
  MomentSpec s;
  s.channels = [](const ParamSet&) { return 2; };
  s.clearValue = [](const ParamSet& p) {
    const double c = warpExponent(p, "ewgf.exponent");
    return std::vector<float>{float(std::exp(c)), float(std::exp(2 * c))};
  };
  s.defines = warpDefine;
  s.hasVariance = true;
  return s;
}

MomentSpec msmSpec() {
  MomentSpec s;
  s.channels = [](const ParamSet&) { return 4; };
  s.clearValue = [](const ParamSet& p) {
    if (!p.b("msm.quantize")) return std::vector<float>{1, 1, 1, 1};
    // Column sums of the quantization matrix (msm.glsl) plus the offset: Q * (1,1,1,1).
    return std::vector<float>{float(-2.07224649 + 32.23703778 - 68.571074599 + 39.3703274134 + 0.035955884801),
                              float(13.7948857237 - 59.4683975703 + 82.0359750338 - 35.364903257),
                              float(0.105877704 - 1.9077466311 + 9.3496555107 - 6.6543490743),
                              float(9.7924062118 - 33.7652110555 + 47.9456096605 - 23.9728048165)};
  };
  s.defines = [](const ParamSet& p) { return std::string(p.b("msm.quantize") ? "#define SL_MSM_QUANTIZED\n" : ""); };
  s.hasVariance = true;
  return s;
}

// sin(c_k u), cos(c_k u) of u = 0.9 z for k = 1..terms: the basis images at depth z
// (convolution_series.glsl's convolutionBasis), what convolution and CSM-Z store first.
std::vector<float> convolutionBasisAt(int terms, double z) {
  std::vector<float> v;
  const double u = kConvolutionSpan * z;
  for (int k = 1; k <= terms; ++k) {
    const double ck = kPi * (2 * k - 1);
    v.push_back(float(std::sin(ck * u)));
    v.push_back(float(std::cos(ck * u)));
  }
  return v;
}

MomentSpec convolutionSpec() {
  MomentSpec s;
  s.channels = [](const ParamSet& p) { return 2 * p.i("convolution.terms"); };
  s.clearValue = [](const ParamSet& p) { return convolutionBasisAt(p.i("convolution.terms"), 1.0); };
  s.defines = [](const ParamSet& p) {
    return "#define SL_CONVOLUTION_TERMS " + std::to_string(p.i("convolution.terms")) + "\n";
  };
  s.fourier = true;
  return s;
}

ParamDecl exponent(const std::string& key, double value, const std::string& help) {
  return {.key = key,
          .type = ParamType::Float,
          .min = 0.01,
          .max = 100,
          .defaultValue = value,
          .help = help + " (clamped to 5.54 in float16 and 42 in float32 storage)",
          .logScale = true};
}

std::vector<ParamDecl> esmParams() {
  return {{.key = "esm.exponent",
           .type = ParamType::Float,
           .min = 1,
           .max = 1000,
           .defaultValue = 80,
           .help = "exponent c: sharper and less leaking when larger (log-space filtering: any value is safe in "
                   "every format)",
           .logScale = true}};
}

std::vector<ParamDecl> evsmParams() {
  return {{.key = "evsm.warps",
           .type = ParamType::Enum,
           .defaultValue = 1,
           .help = "positive warp only (2 moments) or positive and negative (4 moments, min of the two bounds)",
           .choices = {"positive", "both"}},
          exponent("evsm.exponent_pos", 40, "positive warp exponent c+"),
          exponent("evsm.exponent_neg", 5, "negative warp exponent c-"),
          minVariance("evsm.min_variance", 1e-6),
          bleed("evsm.bleed")};
}

std::vector<ParamDecl> msmParams() {
  return {{.key = "msm.moment_bias",
           .type = ParamType::Float,
           .min = 0,
           .max = 0.01,
           .defaultValue = 3e-5,
           .help = "moments pulled toward those of a uniform distribution (keeps the Hankel matrix invertible "
                   "after quantization)",
           .logScale = true},
          {.key = "msm.quantize",
           .type = ParamType::Bool,
           .defaultValue = 0,
           .help = "store through the paper's optimized affine quantization (for 16-bit storage)"}};
}

// The series' shaping, shared by convolution and convolution-soft (convolution_series.glsl).
std::vector<ParamDecl> convolutionShapeParams() {
  return {{.key = "convolution.alpha",
           .type = ParamType::Float,
           .min = 0,
           .max = 10,
           .defaultValue = 1,
           .help = "attenuation exp(-alpha (k/M)^2) of term k against ringing"},
          {.key = "convolution.scale",
           .type = ParamType::Float,
           .min = 1,
           .max = 8,
           .defaultValue = 4,
           .help = "steepens the reconstruction about 1/2 before clamping to [0,1]"},
          {.key = "convolution.offset",
           .type = ParamType::Float,
           .min = 0,
           .max = 0.2,
           .defaultValue = 0.015,
           .unit = "depth [0,1]",
           .help = "receiver moved toward the light so that its own surface reads lit"}};
}

std::vector<ParamDecl> convolutionParams() {
  std::vector<ParamDecl> decls = {{.key = "convolution.terms",
                                   .type = ParamType::Int,
                                   .min = 1,
                                   .max = 16,
                                   .defaultValue = 8,
                                   .unit = "terms",
                                   .help = "Fourier terms M: 2M basis images in ceil(M/2) RGBA targets"}};
  const std::vector<ParamDecl> shape = convolutionShapeParams();
  decls.insert(decls.end(), shape.begin(), shape.end());
  return decls;
}

std::vector<ParamDecl> convolutionSoftParams() {
  std::vector<ParamDecl> decls = {
      {.key = "csmz.terms",
       .type = ParamType::Int,
       .min = 1,
       .max = 7,
       .defaultValue = 4,
       .unit = "terms",
       .help = "Fourier terms M: 2M basis images, 2M times depth and depth: 4M + 1 floats (7 fill 8 targets)"},
      {.key = "csmz.sharpen",
       .type = ParamType::Float,
       .min = 0,
       .max = 16,
       .defaultValue = 4,
       .help = "A of the contact sharpening s^p, p = 1 + A exp(-B gap): darkens the series' leak near contacts"},
      {.key = "csmz.sharpen_falloff",
       .type = ParamType::Float,
       .min = 0,
       .max = 100,
       .defaultValue = 10,
       .unit = "1/world unit",
       .help = "B: how fast the sharpening fades with the receiver-to-blocker distance (world units, not map "
               "depth, so that refitting the map's depth range leaves it alone)"}};
  const std::vector<ParamDecl> shape = convolutionShapeParams();
  decls.insert(decls.end(), shape.begin(), shape.end());
  return decls;
}

// CSM-Z's channels at depth z (convolution-soft.glsl): the basis, the basis times u = 0.9 z, u.
std::vector<float> convolutionSoftMoments(int terms, double z) {
  std::vector<float> channels = convolutionBasisAt(terms, z);
  const float u = float(kConvolutionSpan * z);
  for (int c = 0; c < 2 * terms; ++c) channels.push_back(u * channels[static_cast<size_t>(c)]);
  channels.push_back(u);
  return channels;
}

MomentSpec convolutionSoftSpec() {
  MomentSpec s;
  s.channels = [](const ParamSet& p) { return 4 * p.i("csmz.terms") + 1; };
  s.clearValue = [](const ParamSet& p) { return convolutionSoftMoments(p.i("csmz.terms"), 1.0); };
  s.defines = [](const ParamSet& p) {
    return "#define SL_CONVOLUTION_TERMS " + std::to_string(p.i("csmz.terms")) + "\n";
  };
  s.fourier = true;
  s.softName = "convolution-soft";
  s.pointLightChannels = [](const ParamSet& p) { return 2 * p.i("csmz.terms"); };
  return s;
}

MomentSpec vssmSpec() {
  MomentSpec s = twoMoments();
  s.softName = "vssm";
  return s;
}

std::vector<ParamDecl> lvsmParams() {
  return {{.key = "lvsm.layers",
           .type = ParamType::Int,
           .min = 1,
           .max = 16,
           .defaultValue = 4,
           .unit = "layers",
           .help = "equal depth layers, each with its own two moments (2 channels per layer)"},
          minVariance("lvsm.min_variance", 1e-5)};
}

MomentSpec lvsmSpec() {
  MomentSpec s;
  s.channels = [](const ParamSet& p) { return 2 * p.i("lvsm.layers"); };
  // Depth 1 warps to 1 in every layer.
  s.clearValue = [](const ParamSet& p) {
    return std::vector<float>(static_cast<size_t>(2 * p.i("lvsm.layers")), 1.0f);
  };
  s.defines = [](const ParamSet& p) { return "#define SL_LVSM_LAYERS " + std::to_string(p.i("lvsm.layers")) + "\n"; };
  s.hasVariance = true;
  return s;
}

MomentSpec esmSpec() {
  return {.channels = [](const ParamSet&) { return 1; },
          .clearValue = [](const ParamSet&) { return std::vector<float>{1.0f}; },
          .logFilter = true,
          .logExponentKey = "esm.exponent"};
}

}  // namespace

void registerPrefilteredRepresentations(std::vector<std::unique_ptr<Representation>>& out) {
  const std::string dir = "representations/prefiltered/";
  auto add = [&](std::string id, std::string help, std::vector<ParamDecl> params, MomentSpec spec) {
    const std::string module = dir + id + ".glsl";
    out.push_back(std::make_unique<PrefilteredRepresentation>(std::move(id), std::move(help), module, std::move(params),
                                                              std::move(spec)));
  };
  add("vsm", "variance shadow map (Donnelly & Lauritzen 2006): moments z, z^2; one-tailed Chebyshev bound",
      {minVariance("vsm.min_variance", 1e-5), bleed("vsm.bleed")}, twoMoments());
  add("esm", "exponential shadow map (Annen et al. 2008): exp(c (z - d)), depth filtered in log space", esmParams(),
      esmSpec());
  add("evsm", "exponential variance shadow map: Chebyshev bounds on exponentially warped depth", evsmParams(),
      evsmSpec());
  add("gaussian", "Gaussian filtering (Gumbau et al. 2013): VSM moments read as a Gaussian CDF",
      {minVariance("gaussian.min_variance", 1e-7)}, twoMoments());
  add("ewgf", "exponentially warped Gaussian filtering (Gumbau et al. 2013): Gaussian CDF on warped-depth moments",
      {exponent("ewgf.exponent", 10, "warp exponent c"), minVariance("ewgf.min_variance", 1e-7)}, ewgfSpec());
  add("msm", "moment shadow map (Peters & Klein 2015): 4 moments, Hamburger reconstruction", msmParams(), msmSpec());
  add("lvsm", "layered variance shadow map (Lauritzen & McCool 2008): VSM moments per depth layer", lvsmParams(),
      lvsmSpec());
  add("convolution", "convolution shadow map (Annen et al. 2007): Fourier series of the step, M terms",
      convolutionParams(), convolutionSpec());
  // Soft (techniques/soft/README.md): the PCSS steps with both filters read from the table.
  add("vssm",
      "variance soft shadow map (Yang et al. 2010): blocker depth from the VSM moments of the search box, "
      "penumbra box from the summed-area table",
      // 1e-4, not VSM's 1e-5: a 2048^2 table's 32-bit sums cancel to variance noise of that order
      // in small boxes (speckled false shadow: 0.44 % of `contact` at 1e-5, 0.02 % at 1e-4).
      {minVariance("vssm.min_variance", 1e-4),
       bleed("vssm.bleed"),
       {.key = "vssm.subdivide",
        .type = ParamType::Int,
        .min = 0,
        .max = 2,
        .defaultValue = 0,
        .unit = "levels",
        .help = "kernel subdivision (Yang et al. 2010): where the whole blocker-search box gives no estimate (the "
                "receiver not beyond its mean depth), estimate 2^levels x 2^levels sub-boxes and combine them; 0: "
                "off (the default: compared with the pixel's own depth, sub-boxes of a sloped receiver find "
                "blockers that are not there, techniques/soft/README.md)"}},
      vssmSpec());
  add("convolution-soft",
      "soft convolution shadow map (Annen et al. 2008, CSM-Z): blocker depth from the basis times depth, "
      "penumbra box from the summed-area table, contact sharpening",
      convolutionSoftParams(), convolutionSoftSpec());
}

void addPrefilteredPresets(std::vector<Preset>& out) {
  auto add = [&out](std::string id, std::string help, std::string rep, std::vector<std::string> overrides) {
    out.push_back({std::move(id), std::move(help), "focused", std::move(rep), "none", std::move(overrides)});
  };
  add("vsm", "focused variance shadow map, 5x5 blur", "vsm", {});
  add("esm", "focused exponential shadow map, log-space 5x5 blur", "esm", {});
  add("evsm2", "focused EVSM, positive warp (2 moments)", "evsm", {"evsm.warps=positive"});
  add("evsm4", "focused EVSM, both warps (4 moments)", "evsm", {"evsm.warps=both"});
  // 16-bit coefficients: each is an average of sines and cosines in [-1, 1], which half floats
  // hold to 5e-4, far below the series' own ringing; the same wrong pixels as 32-bit on basic,
  // terrain and sponza, the blur a fifth cheaper (techniques/prefiltered/cost.md, "Storage").
  add("convolution", "focused convolution shadow map, 8 Fourier terms, 16-bit", "convolution",
      {"filter.format=float16"});
  add("gaussian", "focused Gaussian-filtered shadow map (Gumbau et al.)", "gaussian", {});
  add("ewgf", "focused exponentially warped Gaussian filtering (Gumbau et al.)", "ewgf", {});
  add("msm", "focused moment shadow map, 32-bit moments", "msm", {});
  // 16-bit moments: each layer's moments are of depth warped into that layer, the precision the
  // layering buys (Lauritzen & McCool 2008); measured as for convolution above.
  add("lvsm", "focused layered VSM, 4 depth layers, 16-bit", "lvsm", {"filter.format=float16"});
  add("msm16", "focused moment shadow map, 16-bit optimized quantization", "msm",
      // 2e-4, not the paper's 6e-5: 16-bit moments of a long light depth range leaked under a low
      // sun (Sponza 3 degrees: 6.4 % false light); measured in techniques/prefiltered/README.md.
      {"filter.format=float16", "msm.quantize=on", "msm.moment_bias=2e-4"});
  add("vssm", "focused variance soft shadow map: PCSS steps over VSM moments by summed-area table", "vssm", {});
  // Four terms step too gently for the shared offset 0.015: a lit receiver would read its own
  // texels half shadowed (97.8 % wrong pixels on `contact`; 1.9 % at 0.04, techniques/soft/README.md).
  add("convolution-soft", "focused soft convolution shadow map (CSM-Z), 4 Fourier terms", "convolution-soft",
      {"convolution.offset=0.04"});
}

}  // namespace sl
