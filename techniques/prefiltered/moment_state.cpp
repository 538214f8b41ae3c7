#include "prefiltered/moment_state.h"
#include "part/transient_textures.h"

#include "gl/texture_units.h"
#include "prefiltered/moment_views.h"
#include "part/frame_graph.h"
#include "scene/scene_effects.h"
#include "part/penumbra_params.h"

#include <cmath>
#include <cstdio>

namespace sl {

namespace {

GLenum formatFor(int channels, int bits) {
  // Two-moment representations use RG: half the bandwidth of RGBA in every blur tap and lookup.
  if (channels == 1) return bits == 16 ? GL_R16F : GL_R32F;
  if (channels == 2) return bits == 16 ? GL_RG16F : GL_RG32F;
  return bits == 16 ? GL_RGBA16F : GL_RGBA32F;
}

// The status line's note of the share of the map the blur or table filtered (filter.skip_unread).
std::string filteredNote(const char* what, double share) {
  char text[128];
  std::snprintf(text, sizeof text, "%s over %.0f %% of the map (the texels visible receivers read)", what,
                100.0 * share);
  return text;
}

// Half the widest box a soft lookup reads in `view` (texels), mirroring representations/soft/
// penumbra.glsl: the blocker search's radius or the penumbra's, whichever can be larger, at the
// farthest receiver, within [kPcssMinRadius = 1, pcss.max_radius]; under a point of light the
// minimum kernel's. The search is measured at the near plane clamped to 1e-4, the penumbra from
// blockers that may lie as near as the view's near plane (negative for a sun's box).
float softReachTexels(const LightView& view, const Light& light, float lightScale, float maxRadius) {
  if (!(light.radius > 0.0f)) return 1.0f;
  const float size = light.radius * lightScale;
  const float nearD = view.nearPlane, farD = view.farPlane;
  float texels = maxRadius;
  if (light.positional() && view.perspective && nearD > 0.0f && farD > nearD)
    // search size (dR - near) / dR / (z near); penumbra size (1 / dB - 1 / dR) / z, dB >= near
    texels = size * (farD - nearD) / farD / (view.texelWorldSize * nearD);
  else if (light.positional() && nearD > 0.0f && farD > nearD)  // penumbra size (dR - dB) / dB / z
    texels = size * (farD - nearD) / nearD / view.texelWorldSize;
  else if (!light.positional() && !view.perspective)  // size (dR - dB) / texel, dB >= near
    texels = size * (farD - std::min(nearD, 1e-4f)) / view.texelWorldSize;
  else if (!light.positional() && nearD > 0.0f && farD > nearD)  // size (dR - dB) / (z dR)
    texels = size * (farD - nearD) / farD / view.texelWorldSize;
  return std::isfinite(texels) ? std::clamp(texels, 1.0f, maxRadius) : maxRadius;
}

int mipLevels(int size) { return static_cast<int>(std::floor(std::log2(static_cast<double>(size)))) + 1; }

}  // namespace

std::string MomentMapState::statusIn(const SceneEffects& fx, const ParamSet& params) const {
  if (!spec_.soft()) return hardShadowNote(fx);
  if (!fx.areaLight) return spec_.softName + ": point light (radius 0): no blocker estimate, minimum-kernel box";
  return softLightStatus(spec_.softName, fx, params);
}

MomentMapState::~MomentMapState() {
  if (sampler_) glDeleteSamplers(1, &sampler_);
  if (groups_) glDeleteBuffers(1, &groups_);
  if (polygonVao_) glDeleteVertexArrays(1, &polygonVao_);
  if (spans_) glDeleteBuffers(1, &spans_);
  if (columns_) glDeleteBuffers(1, &columns_);
}

void MomentMapState::setScene(const Scene& scene, const Light& light) {
  areaLight_ = sceneEffects(scene, light).areaLight;
}

void MomentMapState::configure(const ParamSet& params) {
  MomentConfig c;
  c.channels = spec_.channels(params);
  const bool soft = spec_.soft();
  c.method = soft ? FilterMethod::Sat : static_cast<FilterMethod>(params.i("filter.method"));
  // Summed-area tables need 32-bit sums whatever the format asked for.
  c.bits = c.method == FilterMethod::Sat ? 32 : formatBits(params);
  c.width = soft ? 1 : params.i("filter.width");
  if (c.channels < 1 || c.channels > 32)
    throw ParamError("pre-filtered representation stores " + std::to_string(c.channels) +
                     " floats per texel (1 to 32 fit in 8 targets)");
  if (!(c == config_)) depth_ = Texture2D();  // reallocated by prepare
  config_ = c;
  clear_ = spec_.clearValue(params);
  clear_.resize(static_cast<size_t>(4 * c.targets()), 0.0f);
  defines_ = spec_.defines ? spec_.defines(params) : "";
  logExponent_ = spec_.logFilter ? params.f(spec_.logExponentKey) : 0.0f;
  skipUnread_ = params.b("filter.skip_unread");
  summed_ = c.method == FilterMethod::Sat && !(soft && !areaLight_);
  pointLightTargets_ = spec_.pointLightChannels ? (spec_.pointLightChannels(params) + 3) / 4 : c.targets();
  // The widest box a lookup reads: the soft ones' search and penumbra boxes are at most
  // pcss.max_radius texels either side; the others' is filter.width.
  satReach_ = soft ? params.f("pcss.max_radius") : 0.5f * static_cast<float>(c.width);
  lightScale_ = soft ? params.f("pcss.light_scale") : 0.0f;
}

void MomentMapState::allocate(int size, int layers) {
  const int levels = config_.method == FilterMethod::Mipmap ? mipLevels(size) : 1;
  depth_ = Texture2D::array(GL_DEPTH_COMPONENT32F, size, size, layers, 1, "moment map depth");
  moments_.clear();
  for (int t = 0; t < config_.targets(); ++t) {
    const GLenum format = formatFor(config_.channelsOf(t), config_.bits);
    moments_.push_back(Texture2D::array(format, size, size, layers, levels, "moments " + std::to_string(t)));
  }
  satRect_ = glm::ivec4(0, 0, size - 1, size - 1);
  // A table covers only the texels lookups read; the rest keep what an earlier frame left, and
  // start at zero rather than undefined.
  if (config_.method == FilterMethod::Sat)
    for (auto& m : moments_) glClearTexImage(m.id(), 0, GL_RGBA, GL_FLOAT, nullptr);
  shadowFbos_.clear();
  for (int l = 0; l < layers; ++l) {
    shadowFbos_.emplace_back("moment map layer " + std::to_string(l));
    shadowFbos_.back().attachLayer({}, &depth_, l);
  }
}

void MomentMapState::prepare(int size, int layers, int /*views*/) {
  if (!sampler_) {
    glCreateSamplers(1, &sampler_);
    label(GL_SAMPLER, sampler_, "moment map: filtered");
  }
  // Moments are filtered like colour: bilinear within a level, trilinear across mip levels.
  const bool mips = config_.method == FilterMethod::Mipmap;
  glSamplerParameteri(sampler_, GL_TEXTURE_MIN_FILTER, mips ? GL_LINEAR_MIPMAP_LINEAR : GL_LINEAR);
  glSamplerParameteri(sampler_, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glSamplerParameteri(sampler_, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  if (depth_ && depth_.width() == size && depth_.layers() == layers) return;
  allocate(size, layers);
}

void MomentMapState::beginShadowLayer(int layer) {
  const Framebuffer& fbo = shadowFbos_.at(static_cast<size_t>(layer));
  fbo.bind();
  glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
}

void MomentMapState::continueShadowLayer(int layer) { shadowFbos_.at(static_cast<size_t>(layer)).bind(); }

std::string MomentMapState::addPasses(FrameGraph& graph, const PartContext& ctx) {
  status_ = ctx.scene ? statusIn(sceneEffects(*ctx.scene, ctx.shadowedLight()), *ctx.params) : "";
  // One pass makes the filtered moments of the depth the shadow pass drew.
  const std::string out = "moments.filtered" + ctx.viewportTag;
  ShaderLibrary* shaders = ctx.shaders;
  auto draw = ctx.drawFullscreen;
  auto bindTechnique = ctx.bindTechnique;
  const std::string name = summed_                                  ? "prefilter.sat"
                           : config_.method == FilterMethod::Mipmap ? "prefilter.mips"
                           : config_.blurs()                        ? "prefilter.blur"
                                                                    : "prefilter.moments";
  // The blur's first direction lands in scratch targets the frame graph lends for the pass (one
  // per moments target, of its format and size); mip-maps and tables need none.
  std::vector<std::string> writes = {out};
  const std::vector<TextureDesc> descs = scratchTargets();
  for (size_t t = 0; t < descs.size(); ++t) {
    writes.push_back("moments.scratch" + std::to_string(t) + ctx.viewportTag);
    graph.createTexture(writes.back(), descs[t]);
  }
  const std::vector<std::string> scratch(writes.begin() + 1, writes.end());
  // The light space is read when the pass runs: a layout pass may have replaced it since. The
  // texels the blur skips keep an earlier frame's moments unless a view shows them.
  const LightSpace* lightSpace = ctx.lightSpace;
  const Light light = ctx.shadowedLight();
  bool shown = false;
  for (const std::string& v : views()) {
    const auto it = ctx.viewTargets.find(v);
    shown = shown || (it != ctx.viewTargets.end() && it->second);
  }
  graph.add({name + ctx.viewportTag,
             {ctx.shadowMap},
             writes,
             [this, shaders, draw, bindTechnique, &graph, scratch, lightSpace, light, shown] {
               std::vector<Texture2D*> targets;
               for (const std::string& s : scratch) targets.push_back(&transientTexture(graph, s));
               std::vector<std::vector<glm::vec2>> hulls;
               // A hull per layer; views sharing a layer: every texel may be read.
               viewReach_.clear();
               if (lightSpace && !lightSpace->sharesLayers())
                 for (const LightView& v : lightSpace->views) {
                   hulls.push_back(v.receiverHull);
                   if (spec_.soft()) viewReach_.push_back(softReachTexels(v, light, lightScale_, satReach_));
                 }
               const double share = filter(*shaders, draw, targets, bindTechnique, hulls, shown);
               if (share < 1.0)
                 status_ += (status_.empty() ? "" : "; ") + filteredNote(summed_           ? "summed-area table"
                                                                         : config_.blurs() ? "blur"
                                                                                           : "moments",
                                                                         share);
             }});
  addMomentViewPasses(graph, ctx, out, views());
  return out;
}

std::vector<TextureDesc> MomentMapState::scratchTargets() const {
  std::vector<TextureDesc> out;
  if (!config_.blurs()) return out;
  for (const Texture2D& m : moments_) out.push_back({m.format(), m.width(), m.height(), std::max(m.layers(), 1), 1});
  return out;
}

void MomentMapState::bind(const Program& p, TextureUnits& units) const {
  // Only programs that sample the moments get them: the shadow pass includes the module too,
  // and binding the targets it renders into would be a feedback loop.
  if (glGetUniformLocation(p.id(), "u_moments0") < 0) return;
  for (int t = 0; t < config_.targets(); ++t) {
    units.bind(p, "u_moments" + std::to_string(t), moments_[static_cast<size_t>(t)].id(), sampler_);
  }
  // Where the tables' corners may be read, in the lookup's units (texel (i, j) holds the sum up
  // to (i + 1, j + 1)): from the first texel the spans reach to the last. A table has no zero
  // line before its first texel: a box touching it shrinks by up to a texel, as at the map's edge.
  if (summed_) p.set("u_satBounds", glm::vec4(satRect_) + 1.0f);
  if (summed_) bindStorage("SatOffsets", satBuffers_.offsets);
}

std::string MomentMapState::defines() const {
  std::string d = "#define SL_MOMENT_TARGETS " + std::to_string(config_.targets()) + "\n";
  d += "#define SL_MOMENT_FLOAT_BITS " + std::to_string(config_.bits) + "\n";
  if (config_.method == FilterMethod::Mipmap) d += "#define SL_MOMENT_MIPMAP\n";
  if (summed_) d += "#define SL_MOMENT_SAT\n";
  if (spec_.soft() && !summed_) d += "#define SL_MOMENT_READ_TARGETS " + std::to_string(pointLightTargets_) + "\n";
  if (spec_.logFilter) d += "#define SL_MOMENT_LOG_FILTER\n";
  return d + defines_;
}

std::vector<std::string> MomentMapState::views() const {
  return momentViewNames(spec_.hasVariance, spec_.fourier, spec_.soft());
}

long long MomentMapState::texels() const {
  long long perLayer = static_cast<long long>(depth_.width()) * depth_.height();
  // Colour targets are counted in stored floats per texel over four, plus the depth.
  return perLayer * std::max(depth_.layers(), 1) * (1 + static_cast<long long>(config_.targets()));
}

}  // namespace sl
