#include "deep/deep_state.h"
#include "gl/storage_blocks.h"
#include "part/part_view.h"

#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "part/frame_graph.h"
#include "part/part.h"
#include "scene/scene_effects.h"

#include <algorithm>

namespace sl {

namespace {

// SSBO bindings shared with passes/deep_fragments.frag and passes/deep_compress.comp.

}  // namespace

DeepState::~DeepState() {
  releaseBuffers();
  if (emptyFbo_) glDeleteFramebuffers(1, &emptyFbo_);
}

void DeepState::releaseBuffers() {
  GLuint b[3] = {fragmentCounts_, fragments_, overflowBuffer_};
  for (GLuint id : b)
    if (id) glDeleteBuffers(1, &id);
  fragmentCounts_ = fragments_ = overflowBuffer_ = 0;
  bufferTexels_ = bufferFragments_ = 0;
}

void DeepState::setScene(const Scene& scene, const Light&) { active_ = sceneEffects(scene).semiTransparent; }

void DeepState::configure(const ParamSet& params) {
  nodeCount_ = params.i("deep.nodes");
  maxFragments_ = params.i("deep.fragments");
  deepSize_ = params.i("deep.size");
  steps_ = params.i("deep.volume_steps");
  samplesAsked_ = params.i("deep.samples");
}

void DeepState::prepare(int size, int layers, int views) {
  opaque_.prepare(size, layers, views);
  views_ = views;  // the node lists are per light view, packed or not
  if (!active_) return;
  if (!nodes_ || nodes_.width() != deepSize_ || nodes_.layers() != views * nodeCount_) {
    nodes_ = Texture2D::array(GL_RG32F, deepSize_, deepSize_, views * nodeCount_, 1, "deep shadow map nodes");
    counts_ = Texture2D::array(GL_R32F, deepSize_, deepSize_, views, 1, "deep shadow map node counts");
  }
  const size_t texels = static_cast<size_t>(deepSize_) * deepSize_ * views;
  const size_t fragments = texels * static_cast<size_t>(maxFragments_);
  if (texels != bufferTexels_ || fragments != bufferFragments_) {
    releaseBuffers();
    glCreateBuffers(1, &fragmentCounts_);
    glNamedBufferStorage(fragmentCounts_, static_cast<GLsizeiptr>(texels * sizeof(GLuint)), nullptr,
                         GL_DYNAMIC_STORAGE_BIT);
    glCreateBuffers(1, &fragments_);
    glNamedBufferStorage(fragments_, static_cast<GLsizeiptr>(fragments * 2 * sizeof(float)), nullptr, 0);
    glCreateBuffers(1, &overflowBuffer_);
    glNamedBufferStorage(overflowBuffer_, kOverflowBytes, nullptr, GL_DYNAMIC_STORAGE_BIT);
    label(GL_BUFFER, fragmentCounts_, "deep fragment counts");
    label(GL_BUFFER, fragments_, "deep fragment lists");
    label(GL_BUFFER, overflowBuffer_, "deep overflow counters");
    bufferTexels_ = texels;
    bufferFragments_ = fragments;
  }
  if (!emptyFbo_) {
    glCreateFramebuffers(1, &emptyFbo_);
    label(GL_FRAMEBUFFER, emptyFbo_, "deep fragments (no attachments)");
  }
  glNamedFramebufferParameteri(emptyFbo_, GL_FRAMEBUFFER_DEFAULT_WIDTH, deepSize_);
  glNamedFramebufferParameteri(emptyFbo_, GL_FRAMEBUFFER_DEFAULT_HEIGHT, deepSize_);
  setSampleCount();
}

// The light image is supersampled (Lokovic & Veach 2000, section 4.1: a texel's function is the
// filtered average of its samples' functions): deep.samples rounded down to a power of two the
// implementation offers. How many it rasterized, the fragment pass records (gl_NumSamples; Mesa
// reports GL_SAMPLES = 0 for a framebuffer without attachments) and the compress pass divides by.
void DeepState::setSampleCount() {
  GLint maxSamples = 1;
  glGetIntegerv(GL_MAX_FRAMEBUFFER_SAMPLES, &maxSamples);
  int asked = 1;
  while (asked * 2 <= std::min(samplesAsked_, std::max(maxSamples, 1))) asked *= 2;
  glNamedFramebufferParameteri(emptyFbo_, GL_FRAMEBUFFER_DEFAULT_SAMPLES, asked > 1 ? asked : 0);
}

std::string DeepState::defines() const {
  if (!active_) return "";
  return "#define SL_DEEP\n#define SL_DEEP_NODES " + std::to_string(nodeCount_) + "\n#define SL_DEEP_FRAGMENTS " +
         std::to_string(maxFragments_) + "\n#define SL_DEEP_STEPS " + std::to_string(steps_) + "\n";
}

void DeepState::bind(const Program& p, TextureUnits& units) const {
  opaque_.bind(p, units);
  if (!active_ || !nodes_) return;
  units.bind(p, "u_deepNodes", nodes_.id());
  units.bind(p, "u_deepCounts", counts_.id());
  for (size_t i = 0; i < windows_.size(); ++i)
    p.set("u_deepWindow[" + std::to_string(i) + "]", glm::vec4(windows_[i].origin, windows_[i].size));
}

// Listed in every scene (views are offered before the first frame); without semi-transparent
// casters the view is a plain dark grey.
std::vector<std::string> DeepState::views() const { return {"deep-nodes"}; }

std::string DeepState::status() const {
  if (!active_) return "deep: no semi-transparent casters, depth map only";
  // The newest counters that have arrived, without waiting for this frame's.
  if (overflowCopies_) overflowCopies_->poll();
  const auto arrived = [this](size_t index) { return overflowCopies_ ? overflowCopies_->value<unsigned>(index) : 0u; };
  const unsigned dropped = arrived(0), relaxed = arrived(1);
  const int samples = std::max(static_cast<int>(arrived(2)), 1);
  std::string s = "deep: " + std::to_string(deepSize_) + "² texels × " + std::to_string(samples) + " samples, " +
                  std::to_string(nodeCount_) + " nodes";
  if (dropped)
    s += "; OVERFLOW: " + std::to_string(dropped) +
         " fragments beyond deep.fragments=" + std::to_string(maxFragments_) + " dropped (raise it)";
  if (relaxed) s += "; " + std::to_string(relaxed) + " texels needed a larger tolerance to fit the nodes";
  return s;
}

long long DeepState::texels() const {
  long long t = opaque_.texels();
  if (active_ && nodes_) t += static_cast<long long>(nodes_.width()) * nodes_.height() * (nodes_.layers() + views_);
  return t;
}

// Each light view's deep map covers the window of it that the semi-transparent casters and the
// volumes reach (deep_fit.h), as far as the viewport can magnify.
void DeepState::fitWindows(const PartContext& ctx) {
  GLint maxDims[2] = {16384, 16384}, boundsRange[2] = {-32768, 32767};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, maxDims);
  glGetIntegerv(GL_VIEWPORT_BOUNDS_RANGE, boundsRange);
  const int reach = std::min({maxDims[0], maxDims[1], -boundsRange[0], boundsRange[1]});
  const int maxMagnify = std::max(reach / std::max(deepSize_, 1), 1);
  windows_.fill(DeepWindow{});
  const auto& views = ctx.lightSpace->views;
  for (size_t i = 0; i < views.size() && i < windows_.size(); ++i)
    windows_[i] = deepFitWindow(*ctx.scene, ctx.time, views[i], deepSize_, maxMagnify);
}

// Every semi-transparent fragment seen from the light goes into its texel's list (depth, alpha);
// a full list counts the fragment as overflow instead of writing past its end.
void DeepState::fragmentsPass(const PartContext& ctx) {
  const GLuint zero = 0;
  glClearNamedBufferData(fragmentCounts_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  glClearNamedBufferData(overflowBuffer_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  bindStorage("DeepCounts", fragmentCounts_);
  bindStorage("DeepFragments", fragments_);
  bindStorage("DeepOverflow", overflowBuffer_);
  glBindFramebuffer(GL_FRAMEBUFFER, emptyFbo_);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_MULTISAMPLE);  // on by default; said here because the samples are the point
  const ProgramSpec spec{"deep fragments", casterStages(*ctx.lightSpace, "passes/deep_fragments.frag"),
                         ctx.techniquePrelude};
  for (int layer = 0; layer < views_; ++layer) {
    // The viewport magnifies the layer's window onto the deep map's texels (deep_fit.h).
    const glm::ivec4 vp = deepViewport(windows_[static_cast<size_t>(layer)], deepSize_);
    glViewport(vp.x, vp.y, vp.z, vp.w);
    ctx.drawSemiTransparent(spec, [&ctx, layer](const Program& p, TextureUnits& units) {
      ctx.bindTechnique(p, units);
      p.set("u_shadowView", layer);
    });
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// Per texel: sort the list, merge it with the volumes ray-marched along the texel's light ray
// into one transmittance function, compress it to at most deep.nodes nodes.
void DeepState::compressPass(const PartContext& ctx) {
  const ProgramSpec spec{"deep compress", {{GL_COMPUTE_SHADER, "passes/deep_compress.comp"}}, ctx.techniquePrelude};
  Program& p = ctx.shaders->get(spec);
  if (!p.valid()) return;
  p.use();
  TextureUnits units;
  ctx.bindTechnique(p, units);
  bindStorage("DeepCounts", fragmentCounts_);
  bindStorage("DeepFragments", fragments_);
  bindStorage("DeepOverflow", overflowBuffer_);
  ctx.bindVolumes();
  glBindImageTexture(0, nodes_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_RG32F);
  glBindImageTexture(1, counts_.id(), 0, GL_TRUE, 0, GL_WRITE_ONLY, GL_R32F);
  p.set("u_deepNodesOut", 0);  // image units (the layout bindings say the same)
  p.set("u_deepCountsOut", 1);
  const GLuint groups = static_cast<GLuint>((deepSize_ + 7) / 8);
  glDispatchCompute(groups, groups, static_cast<GLuint>(views_));
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT);
  // The counters of the status line, copied for a later frame to read (no stall on a GPU).
  if (!overflowCopies_) overflowCopies_ = std::make_unique<ReadbackRing>(kOverflowBytes);
  overflowCopies_->copyFrom(overflowBuffer_);
}

unsigned DeepState::overflow(int index) const {
  if (!overflowCopies_) return 0;
  overflowCopies_->finish();
  return overflowCopies_->value<unsigned>(static_cast<size_t>(index));
}

std::string DeepState::addPasses(FrameGraph& graph, const PartContext& ctx) {
  const std::string& tag = ctx.viewportTag;
  auto view = ctx.viewTargets.find("deep-nodes");
  Texture2D* target = view != ctx.viewTargets.end() ? view->second : nullptr;
  const std::string resource = "view.deep-nodes" + tag;
  if (!active_) {  // nothing semi-transparent: the depth map alone
    if (target) {
      graph.add({resource, {}, {resource}, [target] {
                   Framebuffer fbo("view target");
                   fbo.attach({target}, nullptr);
                   const float grey[4] = {0.2f, 0.2f, 0.2f, 1.0f};
                   glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, grey);
                 }});
      graph.requestSink(resource);
    }
    return ctx.shadowMap;
  }
  fitWindows(ctx);
  const std::string fragments = "deep-fragments" + tag, deep = "deep-compress" + tag;
  graph.add({fragments, {}, {fragments}, [this, ctx] { fragmentsPass(ctx); }});
  graph.add({deep, {ctx.shadowMap, fragments}, {deep}, [this, ctx] { compressPass(ctx); }});
  if (target) {
    graph.add({resource, {deep}, {resource}, [ctx, target] { drawPartView(ctx, target, "views/deep_nodes.frag"); }});
    graph.requestSink(resource);
  }
  return deep;
}

}  // namespace sl
