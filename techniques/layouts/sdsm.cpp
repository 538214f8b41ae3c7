#include "layouts/sdsm.h"
#include "gl/storage_blocks.h"

#include "gl/gl_util.h"
#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "part/light_frame.h"
#include "part/frame_graph.h"

namespace sl {

namespace {

constexpr int kRing = 4;  // latency 0..3: the buffer of frame k is read in frame k + latency

}  // namespace

std::vector<ParamDecl> sdsmParams() {
  return {{.key = "fit.sdsm",
           .type = ParamType::Bool,
           .defaultValue = 0,
           .help = "sample-distribution fitting (Lauritzen et al. 2011): fit to the depths and light-space bounds of "
                   "the pixels actually visible, from a GPU min/max reduction before the shadow pass"},
          {.key = "fit.sdsm_latency",
           .type = ParamType::Int,
           .min = 0,
           .max = 3,
           .defaultValue = 1,
           .unit = "frames",
           .help = "frames between the reduction and the fit that uses it: 0 waits for the GPU in the same frame, "
                   "1-3 read an earlier frame's result without a stall (lags behind camera motion)"}};
}

std::vector<glm::vec3> visibleBoxCorners(const Light& light, const VisibleBounds& visible) {
  const glm::mat4 toWorld = glm::inverse(lightViewMatrix(light, 0.0f));
  const glm::vec3 pad = 0.01f * glm::max(visible.lightMax - visible.lightMin, glm::vec3(1e-3f));
  const glm::vec3 lo = visible.lightMin - pad, hi = visible.lightMax + pad;
  std::vector<glm::vec3> out;
  for (int i = 0; i < 8; ++i) {
    const glm::vec3 q(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, -(i & 4 ? hi.z : lo.z));
    out.emplace_back(toWorld * glm::vec4(q, 1.0f));
  }
  return out;
}

struct SdsmState::Gpu {
  GLuint buffers[kRing] = {};
  Gpu() {
    glCreateBuffers(kRing, buffers);
    for (GLuint b : buffers) {
      glNamedBufferData(b, 8 * sizeof(uint32_t), nullptr, GL_DYNAMIC_READ);
      label(GL_BUFFER, b, "sdsm bounds");
    }
  }
  ~Gpu() { glDeleteBuffers(kRing, buffers); }
  VisibleBounds read(int slot) const {
    uint32_t raw[8];
    glGetNamedBufferSubData(buffers[slot], 0, sizeof(raw), raw);
    VisibleBounds v;
    float f[8];
    for (int i = 0; i < 8; ++i) f[i] = floatFromOrderedBits(raw[i]);
    v.valid = f[0] <= f[1] && std::isfinite(f[0]) && std::isfinite(f[1]);
    v.depthMin = f[0];
    v.depthMax = f[1];
    v.lightMin = glm::vec3(f[2], f[4], f[6]);
    v.lightMax = glm::vec3(f[3], f[5], f[7]);
    return v;
  }
};

SdsmState::SdsmState(const Layout& layout) : LayoutState(layout) {}
SdsmState::~SdsmState() = default;

void SdsmState::reset() {
  frames_ = 0;
  latest_ = VisibleBounds{};
}

LightSpace SdsmState::compute(const LayoutInput& in) {
  lastInput_ = in;
  if (!in.params->b("fit.sdsm")) return layout_.compute(in);
  const int latency = in.params->i("fit.sdsm_latency");
  // The reduction of frame k - latency is complete by now (a finished frame's is, at least).
  if (gpu_ && latency > 0 && frames_ >= latency) latest_ = gpu_->read((frames_ - latency) % kRing);
  LayoutInput withBounds = in;
  withBounds.visible = latest_;
  return layout_.compute(withBounds);
}

// fit.sdsm_latency 0: the reduction runs before the shadow pass over the G-buffer, and this
// frame's fit waits for it. 1-3: a later frame reads it, so it runs after the shading over the
// depth the camera's surfaces were drawn with (addPassesAfterShading): no G-buffer for it,
// which a forward-shaded frame would otherwise draw for this pass alone.
std::vector<std::string> SdsmState::addPasses(FrameGraph& graph, const PartContext& ctx) {
  if (!ctx.params->b("fit.sdsm")) return {};
  if (!gpu_) gpu_ = std::make_unique<Gpu>();
  slot_ = frames_ % kRing;
  ++frames_;
  if (ctx.params->i("fit.sdsm_latency") > 0) return {};
  const std::string res = "sdsm.bounds" + ctx.viewportTag;
  const int slot = slot_;
  graph.add({"sdsm.reduce" + ctx.viewportTag, {"gbuffer"}, {res}, [this, ctx, slot] {
               reduce(ctx, slot, nullptr);
               // No latency: wait for the result and refit this frame's light space with it.
               latest_ = gpu_->read(slot);
               LayoutInput in = lastInput_;
               in.visible = latest_;
               ctx.replaceLightSpace(layout_.compute(in));
             }});
  return {res};
}

void SdsmState::addPassesAfterShading(FrameGraph& graph, const PartContext& ctx, const AccumulationOutput& shaded) {
  if (!gpu_ || !ctx.params->b("fit.sdsm") || ctx.params->i("fit.sdsm_latency") == 0) return;
  const std::string res = "sdsm.bounds" + ctx.viewportTag;
  const int slot = slot_;
  // An accumulation that left no depth target: the G-buffer's positions, so the slot is filled.
  const Texture2D* depth = shaded.depthTex;
  graph.add({"sdsm.reduce" + ctx.viewportTag,
             {depth ? shaded.depth : std::string("gbuffer")},
             {res},
             [this, ctx, slot, depth] { reduce(ctx, slot, depth); }});
  graph.requestSink(res);  // read by a later frame, not by a pass of this one
}

void SdsmState::reduce(const PartContext& ctx, int slot, const Texture2D* depth) {
  ProgramSpec spec{
      "sdsm reduce", {{GL_COMPUTE_SHADER, "passes/depth_bounds.comp"}}, depth ? "#define SL_BOUNDS_FROM_DEPTH\n" : ""};
  Program& p = ctx.shaders->get(spec);
  if (!p.valid()) return;
  const uint32_t init[8] = {~0u, 0u, ~0u, 0u, ~0u, 0u, ~0u, 0u};
  glNamedBufferSubData(gpu_->buffers[slot], 0, sizeof(init), init);
  p.use();
  TextureUnits units;
  // From a depth target the points are in the camera's clip space (passes/depth_bounds.comp).
  const glm::mat4 fromPoint = depth ? glm::inverse(ctx.proj * ctx.view) : glm::mat4(1.0f);
  if (depth)
    units.bind(p, "u_depth", depth->id());
  else
    ctx.bindGBuffer(p, units);
  p.set("u_cameraView", ctx.view * fromPoint);
  p.set("u_lightView", lightViewMatrix(ctx.shadowedLight(), 0.0f) * fromPoint);
  bindStorage("DepthBounds", gpu_->buffers[slot]);
  // 16x16 invocations of 4x4 pixels each (passes/depth_bounds.comp).
  glDispatchCompute((ctx.width + 63) / 64, (ctx.height + 63) / 64, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
}

}  // namespace sl
