// The passes that make the moment maps from the shadow pass's depth: the representation's
// moments of each texel, blurred on the way by a separable box (two compute passes per layer,
// through a scratch target), or then mip-mapped by 2x2 box downsampling, or summed into a table
// (moment_sat.cpp). Filters work in log space for ESM (SL_MOMENT_LOG_FILTER); the mips and
// tables drop non-finite taps, the blur's taps are finite by construction (moment_blur.comp).
#include "gl/storage_blocks.h"
#include "gl/texture_units.h"
#include "prefiltered/blur_spans.h"
#include "prefiltered/moment_state.h"

#include <optional>

namespace sl {

namespace {

std::string filterDefines(const MomentConfig& c, bool logFilter) {
  return "#define SL_MOMENT_TARGETS " + std::to_string(c.targets()) + "\n" +
         (logFilter ? "#define SL_MOMENT_LOG_FILTER\n" : "");
}

void bindSources(const Program& p, TextureUnits& units, const std::vector<const Texture2D*>& src) {
  for (size_t t = 0; t < src.size(); ++t) units.bind(p, "u_src" + std::to_string(t), src[t]->id());
}

std::vector<const Texture2D*> pointers(const std::vector<Texture2D>& v) {
  std::vector<const Texture2D*> out;
  for (const auto& t : v) out.push_back(&t);
  return out;
}

std::vector<const Texture2D*> pointers(const std::vector<Texture2D*>& v) { return {v.begin(), v.end()}; }

}  // namespace

const char* imageFormatName(GLenum format) {
  switch (format) {
    case GL_R16F:
      return "r16f";
    case GL_RG16F:
      return "rg16f";
    case GL_RGBA16F:
      return "rgba16f";
    case GL_R32F:
      return "r32f";
    case GL_RG32F:
      return "rg32f";
    default:
      return "rgba32f";
  }
}

std::optional<BlurGroups> MomentMapState::groupsFor(const std::vector<glm::vec2>& hull) const {
  if (!skipsUnread() || hull.empty()) return std::nullopt;
  const int size = depth_.width();
  return blurGroups(blurSpans(hull, size, kBlurRun, kLookupReach), size, config_.width / 2);
}

void MomentMapState::uploadGroups(const BlurGroups& groups) {
  std::vector<glm::uvec2> both = groups.first;
  both.insert(both.end(), groups.second.begin(), groups.second.end());
  if (both.empty()) both.push_back(glm::uvec2(0));  // a buffer is never empty
  if (!groups_) glCreateBuffers(1, &groups_);
  glNamedBufferData(groups_, static_cast<GLsizeiptr>(both.size() * sizeof(glm::uvec2)), both.data(), GL_STREAM_DRAW);
  bindStorage("SlBlurGroups", groups_);
}

void MomentMapState::clearLayer(int layer) {
  for (size_t t = 0; t < moments_.size(); ++t)
    glClearTexSubImage(moments_[t].id(), 0, 0, 0, layer, moments_[t].width(), moments_[t].height(), 1, GL_RGBA,
                       GL_FLOAT, &clear_[4 * t]);
}

double MomentMapState::filter(ShaderLibrary& shaders, const std::function<void()>& drawFullscreen,
                              const std::vector<Texture2D*>& scratch, const TechniqueBinder& bindTechnique,
                              const std::vector<std::vector<glm::vec2>>& hulls, bool clearUnread) {
  const int layers = std::max(depth_.layers(), 1);
  if (summed_) return buildSat(shaders, bindTechnique, hulls, clearUnread);
  const bool blurs = config_.blurs();
  double share = 0.0;
  for (int l = 0; l < layers; ++l) {
    const std::vector<glm::vec2>* hull =
        skipsUnread() && l < static_cast<int>(hulls.size()) && !hulls[static_cast<size_t>(l)].empty()
            ? &hulls[static_cast<size_t>(l)]
            : nullptr;
    if (!blurs) {  // the moments alone (a box of 1, the first mip level, a soft map under a point of light)
      share += writeMoments(shaders, drawFullscreen, bindTechnique, l, hull, clearUnread);
      continue;
    }
    const std::optional<BlurGroups> groups = hull ? groupsFor(*hull) : std::nullopt;
    share += groups ? groups->share : 1.0;
    std::optional<glm::ivec2> first, second;  // (offset, count) in the group list
    if (groups) {
      uploadGroups(*groups);
      first = glm::ivec2(0, groups->first.size());
      second = glm::ivec2(groups->first.size(), groups->second.size());
    }
    // Depth to moments, blurred on the way along rows; then columns.
    runBlurPass(shaders, bindTechnique, {&depth_}, pointers(scratch), l, false, first);
    if (groups && clearUnread) clearLayer(l);  // a view shows the texels the blur skips
    runBlurPass(shaders, bindTechnique, pointers(scratch), pointers(moments_), l, true, second);
  }
  if (config_.method == FilterMethod::Mipmap) buildMips(shaders, drawFullscreen);
  return share / layers;
}

// The moments of each depth texel of a layer, as a fragment pass (passes/moment_from_depth.frag;
// the rasterizer's colour writes moved them at twice the rate of a compute pass's image stores
// on llvmpipe): over the receiver hull dilated by what a bilinear lookup reads when there is one
// (the other texels keep an earlier frame's moments, or the empty texel's when `clearUnread`), or
// the whole layer. Returns the share of the layer covered.
double MomentMapState::writeMoments(ShaderLibrary& shaders, const std::function<void()>& drawFullscreen,
                                    const TechniqueBinder& bindTechnique, int layer, const std::vector<glm::vec2>* hull,
                                    bool clearUnread) {
  const int n = depth_.width();
  const std::vector<glm::vec2> polygon = hull ? dilatedHull(*hull, n, kLookupReach + 1.0f) : std::vector<glm::vec2>{};
  const bool whole = polygon.size() < 3 || polygon.size() > kMaxPolygonCorners;
  // Under a point of light a soft one's shading reads only its first targets; a view, all.
  const int written = spec_.soft() && !summed_ && !clearUnread ? pointLightTargets_ : config_.targets();
  Program& p = shaders.get({"moments from depth",
                            {{GL_VERTEX_SHADER, whole ? "passes/fullscreen.vert" : "passes/map_polygon.vert"},
                             {GL_FRAGMENT_SHADER, "passes/moment_from_depth.frag"}},
                            defines() + "#include \"" + module_ + "\"\n#define SL_MOMENT_WRITTEN_TARGETS " +
                                std::to_string(written) + "\n"});
  if (!p.valid()) return 1.0;
  if (!whole && clearUnread) clearLayer(layer);
  p.use();
  TextureUnits units;
  bindTechnique(p, units);  // what representationMoments reads (exponents, quantization)
  units.bind(p, "u_depth", depth_.id());
  p.set("u_layer", layer);
  Framebuffer fbo("moments from depth");
  std::vector<const Texture2D*> targets = pointers(moments_);
  targets.resize(static_cast<size_t>(written));
  fbo.attachLayer(targets, nullptr, layer);
  fbo.bind();
  glViewport(0, 0, n, n);
  if (whole) {
    drawFullscreen();
    return 1.0;
  }
  for (size_t i = 0; i < polygon.size(); ++i)
    p.set("u_polygon[" + std::to_string(i) + "]", polygon[i] / static_cast<float>(n));
  // Either winding: the fan is drawn with culling off (the shadow pass may leave it on).
  const GLboolean culling = glIsEnabled(GL_CULL_FACE);
  glDisable(GL_CULL_FACE);
  if (!polygonVao_) glCreateVertexArrays(1, &polygonVao_);
  glBindVertexArray(polygonVao_);
  glDrawArrays(GL_TRIANGLE_FAN, 0, static_cast<GLsizei>(polygon.size()));
  glBindVertexArray(0);
  if (culling) glEnable(GL_CULL_FACE);
  long long covered = 0;
  for (const glm::ivec2 s : polygonSpans(polygon, n, 1)) covered += std::max(0, s.y - s.x + 1);
  return static_cast<double>(covered) / (static_cast<double>(n) * n);
}

void MomentMapState::buildMips(ShaderLibrary& shaders, const std::function<void()>& drawFullscreen) {
  const ProgramSpec spec{
      "moment downsample",
      {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "passes/moment_downsample.frag"}},
      filterDefines(config_, spec_.logFilter)};
  Program& p = shaders.get(spec);
  if (!p.valid()) return;
  p.use();
  if (spec_.logFilter) p.set("u_logExponent", logExponent_);
  const int layers = std::max(depth_.layers(), 1);
  const int levels = moments_.front().levels();
  for (int level = 1; level < levels; ++level) {
    // Reading level-1 while level is attached is only defined when the sampled range excludes
    // the attached level: restrict every target to its source level for this step.
    for (auto& m : moments_) {
      glTextureParameteri(m.id(), GL_TEXTURE_BASE_LEVEL, level - 1);
      glTextureParameteri(m.id(), GL_TEXTURE_MAX_LEVEL, level - 1);
    }
    for (int l = 0; l < layers; ++l) {
      p.set("u_layer", l);
      Framebuffer fbo("moment mip");
      fbo.attachLayer(pointers(moments_), nullptr, l, level);
      fbo.bind();
      TextureUnits units;
      bindSources(p, units, pointers(moments_));
      drawFullscreen();
    }
  }
  for (auto& m : moments_) {
    glTextureParameteri(m.id(), GL_TEXTURE_BASE_LEVEL, 0);
    glTextureParameteri(m.id(), GL_TEXTURE_MAX_LEVEL, levels - 1);
  }
}

// One direction of the box blur as a compute pass (shaders/passes/moment_blur.comp), one layer:
// from the depth (the first direction) or from
// the first direction's scratch targets. On llvmpipe the blur was two fullscreen fragment passes
// fetching every tap; an invocation now fetches each texel of its run once, and the shadow pass
// writes depth alone (docs/performance.md has both measured).
void MomentMapState::runBlurPass(ShaderLibrary& shaders, const TechniqueBinder& bindTechnique,
                                 const std::vector<const Texture2D*>& src, const std::vector<const Texture2D*>& dst,
                                 int layer, bool vertical, std::optional<glm::ivec2> groups) {
  const bool fromDepth = src.front() == &depth_;
  std::string prelude = fromDepth ? defines() + "#include \"" + module_ + "\"\n#define SL_BLUR_FROM_DEPTH\n"
                                  : filterDefines(config_, spec_.logFilter);
  prelude += "#define SL_BLUR_RUN " + std::to_string(kBlurRun) + "\n#define SL_BLUR_HALF " +
             std::to_string(config_.width / 2) + "\n#define SL_BLUR_WIDTH " + std::to_string(config_.width) + "\n";
  if (groups) prelude += "#define SL_BLUR_GROUPS\n";
  for (size_t t = 0; t < dst.size(); ++t)
    prelude += "#define SL_BLUR_FORMAT" + std::to_string(t) + " " + imageFormatName(dst[t]->format()) + "\n";
  Program& p = shaders.get({fromDepth ? "moment blur from depth" : "moment blur",
                            {{GL_COMPUTE_SHADER, "passes/moment_blur.comp"}},
                            prelude});
  if (!p.valid()) return;
  p.use();
  TextureUnits units;
  if (fromDepth) {
    bindTechnique(p, units);  // what representationMoments reads (exponents, quantization)
    units.bind(p, "u_depth", depth_.id());
  } else {
    bindSources(p, units, src);
  }
  if (spec_.logFilter) p.set("u_logExponent", logExponent_);
  p.set("u_layer", layer);
  p.set("u_vertical", vertical ? 1 : 0);
  if (groups) p.set("u_groupOffset", groups->x);
  for (size_t t = 0; t < dst.size(); ++t) {
    glBindImageTexture(static_cast<GLuint>(t), dst[t]->id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, dst[t]->format());
    p.set("u_dst" + std::to_string(t), static_cast<int>(t));
  }
  const GLuint size = static_cast<GLuint>(depth_.width());
  const GLuint runs = (size + kBlurRun - 1) / kBlurRun;
  if (!groups)
    glDispatchCompute((runs + kBlurGroupSide - 1) / kBlurGroupSide, (size + kBlurGroupSide - 1) / kBlurGroupSide, 1);
  else if (groups->y > 0)
    glDispatchCompute(static_cast<GLuint>(groups->y), 1, 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  for (size_t t = 0; t < dst.size(); ++t)
    glBindImageTexture(static_cast<GLuint>(t), 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
}

}  // namespace sl
