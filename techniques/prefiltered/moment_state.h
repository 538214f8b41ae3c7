// The shadow targets of the pre-filtered representations: the depth array the shadow pass draws
// (the nearest caster, as a depth map's), and 1..8 colour texture arrays (a layer per light view,
// 16- or 32-bit float, with mip levels when filtered by mip-mapping) that the filter pass fills
// with the representation's moments of that depth, blurred on the way (or then mip-mapped or
// summed); the visibility tests read them through one bilinear (or trilinear) sampler.
#pragma once

#include "gl/gl_util.h"

#include <glm/glm.hpp>
#include "prefiltered/blur_spans.h"
#include "prefiltered/moment_spec.h"
#include "scene/scene_effects.h"
#include "part/frame_graph.h"
#include "part/part.h"

#include <functional>
#include <optional>
#include <vector>

namespace sl {

enum class FilterMethod { Blur = 0, Mipmap = 1, Sat = 2 };

// What the targets depend on; a change reallocates them.
struct MomentConfig {
  int channels = 2;
  int bits = 32;
  FilterMethod method = FilterMethod::Blur;
  int width = 1;  // box width in texels
  bool operator==(const MomentConfig&) const = default;
  int targets() const { return (channels + 3) / 4; }
  bool blurs() const { return method == FilterMethod::Blur && width > 1; }  // a blur pass, with scratch targets
  int channelsOf(int target) const { return std::min(4, channels - 4 * target); }
};

// The GLSL image format qualifier of a moments target's storage ("rg16f", "rgba32f", ...).
const char* imageFormatName(GLenum format);

class MomentMapState : public RepresentationState {
 public:
  // module: the representation's GLSL module (representationMoments), for the depth-to-moments pass.
  MomentMapState(const MomentSpec& spec, std::string module) : spec_(spec), module_(std::move(module)) {}
  ~MomentMapState() override;
  void setScene(const Scene& scene, const Light& light) override;
  void configure(const ParamSet& params) override;
  void prepare(int size, int layers, int views) override;
  void beginShadowLayer(int layer) override;
  void continueShadowLayer(int layer) override;
  std::string addPasses(FrameGraph& graph, const PartContext& ctx) override;
  void bind(const Program& p, TextureUnits& units) const override;
  std::string defines() const override;
  std::vector<std::string> views() const override;
  const Texture2D* depthTexture() const override { return &depth_; }
  long long texels() const override;
  VisibilityCurve visibilityCurve(const CurveQuery& query) const override;
  // A fixed filter width is no penumbra: in an area-light scene it says it ignores the radius.
  std::string status() const override { return status_; }

  // What the blur's first direction writes: one target like each moments target (level 0 only);
  // none for mip-maps and summed-area tables. The frame graph lends them (transient textures).
  std::vector<TextureDesc> scratchTargets() const;
  // Sets the technique's uniforms on a program that includes the representation's module.
  using TechniqueBinder = std::function<void(const Program&, TextureUnits&)>;
  // Runs the passes that make the moments from the depth now (with the blur, mips or table), as
  // the frame graph's pass does. scratch: the targets of scratchTargets() (lent by the graph).
  // hulls: per layer, where its visible receivers fall (LightView::receiverHull); with
  // filter.skip_unread the blur filters only the texels they can read, and clearUnread writes
  // the moments of an empty texel over the others (a debug view shows them). Returns the share
  // of the map's texels filtered.
  double filter(ShaderLibrary& shaders, const std::function<void()>& drawFullscreen,
                const std::vector<Texture2D*>& scratch, const TechniqueBinder& bindTechnique,
                const std::vector<std::vector<glm::vec2>>& hulls = {}, bool clearUnread = true);
  // The blur (or the moments pass of a box of 1) skips texels no visible receiver reads
  // (filter.skip_unread; the summed-area tables skip by spans of their own, moment_sat.cpp).
  bool skipsUnread() const { return skipUnread_ && config_.method != FilterMethod::Mipmap; }
  const MomentConfig& config() const { return config_; }
  Texture2D& moments(int target) { return moments_.at(static_cast<size_t>(target)); }
  const Texture2D& moments(int target) const { return moments_.at(static_cast<size_t>(target)); }
  const std::vector<float>& clearValue() const { return clear_; }

  // Target `t`'s summed-area table offset as the GPU computed it: a readback that waits (tests).
  glm::vec4 satOffsetOf(int t) const;

 private:
  void allocate(int size, int layers);
  std::string statusIn(const SceneEffects& fx, const ParamSet& params) const;
  // moment_sat.cpp: the tables over the texels lookups read (returns the share of the map).
  double buildSat(ShaderLibrary& shaders, const TechniqueBinder& bindTechnique,
                  const std::vector<std::vector<glm::vec2>>& hulls, bool wholeMap);
  // The texels a layer's table holds: those a visible receiver's lookups read, its receiver
  // hull dilated by the widest box and a bilinear read (nullptr: every texel).
  struct SatCover {
    std::vector<glm::ivec2> rows;     // per row: the columns [x0, x1] (x0 > x1: none)
    std::vector<glm::ivec2> columns;  // per column: the rows [y0, y1] whose span holds it
    glm::ivec4 rect{0};               // (x0, y0, x1, y1): the columns and rows any span reaches
  };
  SatCover satCover(const std::vector<glm::vec2>* hull, int layer) const;
  static void upload(GLuint buffer, const std::vector<glm::ivec2>& data);
  void satOffsets(ShaderLibrary& shaders, const TechniqueBinder& bindTechnique, const std::vector<SatCover>& covers);
  void ensureSatBuffers(size_t targets, size_t layers);
  void buildMips(ShaderLibrary& shaders, const std::function<void()>& drawFullscreen);
  double writeMoments(ShaderLibrary& shaders, const std::function<void()>& drawFullscreen,
                      const TechniqueBinder& bindTechnique, int layer, const std::vector<glm::vec2>* hull,
                      bool clearUnread);
  static constexpr size_t kMaxPolygonCorners = 64;  // passes/map_polygon.vert
  void runBlurPass(ShaderLibrary& shaders, const TechniqueBinder& bindTechnique,
                   const std::vector<const Texture2D*>& src, const std::vector<const Texture2D*>& dst, int layer,
                   bool vertical, std::optional<glm::ivec2> groups);
  // The work groups the blur runs for a layer's receiver hull (none: every group).
  std::optional<BlurGroups> groupsFor(const std::vector<glm::vec2>& hull) const;
  void uploadGroups(const BlurGroups& groups);
  void clearLayer(int layer);
  const MomentSpec& spec_;
  std::string module_;
  MomentConfig config_;
  std::vector<float> clear_;
  std::string defines_;
  std::string status_;
  float logExponent_ = 0.0f;
  GLuint sampler_ = 0;
  GLuint groups_ = 0;
  GLuint polygonVao_ = 0;  // the empty vertex array the receiver polygon's fan is drawn with  // storage block
                           // SlBlurGroups (passes/moment_blur.comp)
  bool skipUnread_ = true;
  // Whether this frame's filter sums tables: the summed-area method, except for the soft ones
  // under a point of light (setScene), whose only box is the minimum kernel's, two texels wide:
  // four bilinear reads of the moments themselves give it (soft_moments.glsl), and no table is
  // made (SL_MOMENT_SAT is then not defined).
  bool summed_ = false;
  bool areaLight_ = true;
  int pointLightTargets_ = 1;  // the targets a soft one reads under a point of light (MomentSpec)  // setScene: the
                               // shadowed light has a radius (without a scene: tables)
  Texture2D depth_;
  std::vector<Texture2D> moments_;
  std::vector<Framebuffer> shadowFbos_;  // per layer: the depth
  // The tables' offsets, computed and kept on the GPU (moment_sat.cpp: satOffsets).
  struct SatBuffers {
    GLuint rowSums = 0, rowCounts = 0, offsets = 0;
    GLsizeiptr rowBytes = 0;
    size_t targets = 0;
    void release() {
      for (GLuint b : {rowSums, rowCounts, offsets})
        if (b) glDeleteBuffers(1, &b);
      rowSums = rowCounts = offsets = 0;
    }
    ~SatBuffers() { release(); }
  } satBuffers_;
  glm::ivec4 satRect_{0};         // the columns and rows the tables' spans reach
  GLuint spans_ = 0;              // storage block SatSpans (passes/moment_sat_*.comp)
  GLuint columns_ = 0;            // storage block SatColumns
  float satReach_ = 0.0f;         // texels: half the widest box a lookup reads
  std::vector<float> viewReach_;  // per layer, where this frame's light view bounds it
  float lightScale_ = 0.0f;       // pcss.light_scale (the soft ones)
};

}  // namespace sl
