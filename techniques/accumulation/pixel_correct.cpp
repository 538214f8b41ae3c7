// Pixel-correct shadow maps (Scherzer et al. 2007): parameters, per-viewport history state,
// Halton jitter and the accumulation / debug-view passes. See techniques/accumulation/README.md.
#include "accumulation/pixel_correct.h"

#include "gl/gl_util.h"
#include "gl/texture_units.h"

#include "part/frame_graph.h"
#include "part/uniforms.h"

#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sl {

float halton(int index, int base) {
  float f = 1.0f, r = 0.0f;
  for (int i = index; i > 0; i /= base) {
    f /= static_cast<float>(base);
    r += f * static_cast<float>(i % base);
  }
  return r;
}

LayoutJitter pixelCorrectJitter(const ParamSet& params, int index) {
  LayoutJitter j;
  const int i = index + 1;  // Halton index 0 is (0,0,0): skip it
  if (params.b("pc.jitter")) {
    const float a = params.f("pc.jitter_amplitude");
    j.offsetTexels = glm::vec2(halton(i, 2) - 0.5f, halton(i, 3) - 0.5f) * a;
  }
  if (params.b("pc.rotate")) j.rotationRad = (2.0f * halton(i, 5) - 1.0f) * glm::radians(params.f("pc.rotation_deg"));
  if (params.b("pc.area_light")) {
    // Halton(7, 11), independent of the texel jitter's bases, mapped to the disk by the
    // concentric map (Shirley & Chiu 1997): uniform in area, strata stay compact.
    const float a = 2.0f * halton(i, 7) - 1.0f, b = 2.0f * halton(i, 11) - 1.0f;
    const float pi4 = glm::quarter_pi<float>();
    if (a != 0.0f || b != 0.0f)
      j.lightSample = std::abs(a) > std::abs(b) ? a * glm::vec2(std::cos(pi4 * b / a), std::sin(pi4 * b / a))
                                                : b * glm::vec2(std::sin(pi4 * a / b), std::cos(pi4 * a / b));
  }
  return j;
}

float pixelCorrectNextExponent(const ParamSet& params, float previous, bool moving, bool haveHistory) {
  const float mMax = params.f("pc.m");
  if (!params.b("pc.adaptive")) return mMax;
  const float mLow = std::min(params.f("pc.m_moving"), mMax);
  // A fresh history (cut, first frame) needs no responsiveness: with warm-up it converges at
  // full m; without, the paper's schedule starts low.
  if (!haveHistory) return params.b("pc.warmup") ? mMax : mLow;
  if (moving) return mLow;
  return std::clamp(previous + params.f("pc.m_step"), mLow, mMax);
}

namespace {

// pc.while_moving = test: while the camera moves, show the layout's plain test, no history.
bool plainTestWhileMoving(const ParamSet& params) { return params.choice("pc.while_moving") == "test"; }

}  // namespace

LayoutJitter PixelCorrectState::jitter(const ParamSet& params, bool cameraMoved) const {
  // Without jitter the layout's own (snapped, world-stable) rasterization is used.
  if (cameraMoved && (!params.b("pc.jitter_moving") || plainTestWhileMoving(params))) return {};
  return pixelCorrectJitter(params, jitterIndex_);
}

void PixelCorrectState::reset() {
  hasHistory_ = false;
  frames_ = 0;
  m_ = 0.0f;
}

std::string PixelCorrectState::status() const {
  if (showingTest_) return "camera moving: plain test (pc.while_moving)";
  char buf[96];
  std::snprintf(buf, sizeof buf, "m = %.1f (%s)%s, frame %d", m_, adaptive_ ? "adaptive" : "fixed",
                keepBest_ ? ", keep best" : "", frames_);
  return buf;
}

void PixelCorrectState::ensureHistory(int w, int h, GLenum format) {
  if (history_[0] && history_[0]->width() == w && history_[0]->height() == h && history_[0]->format() == format) return;
  for (int i = 0; i < 2; ++i) {
    history_[i] = std::make_unique<Texture2D>(format, w, h, "pixel-correct history " + std::to_string(i));
    history_[i]->setFilter(GL_LINEAR, GL_LINEAR);  // the paper's bilinear history lookup
    const float zero[4] = {0, 0, 0, 0};
    glClearTexImage(history_[i]->id(), 0, GL_RGBA, GL_FLOAT, zero);
    fboRaw_[i] = nullptr;
    fboColor_[i] = nullptr;
  }
  hasHistory_ = false;
}

namespace {

// The reprojection inputs and the exponent; the technique's own uniforms and the G-buffer /
// shadow map come from ctx.bindTechniqueInputs.
void setAccumulationUniforms(const Program& p, const glm::mat4& view, const glm::mat4& prevProj, bool hasHistory,
                             float m) {
  p.set("u_view", view);
  p.set("u_invPrevProj", glm::inverse(prevProj));
  p.set("u_hasHistory", hasHistory ? 1.0f : 0.0f);
  p.set("u_m", m);
}

// The scene pass writes the raw test itself, so only the (G-buffer based) views read it.
void bindInputs(const AccumulationContext& ctx, const Program& p, TextureUnits& units, const Texture2D* history,
                bool forViews) {
  ctx.bindTechniqueInputs(p, units);
  units.bind(p, "u_history", history->id());
  if (!forViews) return;
  units.bind(p, "u_gMotion", ctx.gMotion->id());
  units.bind(p, "u_raw", ctx.rawVisibilityTex->id());
}

// The accumulation's debug views (confidence, history, disocclusion) shown this frame: fullscreen
// passes over the G-buffer, the raw test and last frame's history.
void addPixelCorrectViews(FrameGraph& graph, const AccumulationContext& c, const std::vector<std::string>& views,
                          Texture2D* prevTex, const std::string& prelude, bool hasHistory, float m) {
  const std::string& tag = c.viewportTag;
  const std::string prevRes = "pc.history.prev" + tag;
  for (const std::string& name : views) {
    auto it = c.viewTargets.find(name);
    if (it == c.viewTargets.end() || !it->second) continue;
    Texture2D* target = it->second;
    const std::string res = std::string("view.") + name + tag;
    const std::string file = std::string("accumulation/views_") + name + ".frag";
    graph.add({res,
               {"gbuffer", "gbuffer.motion", c.rawVisibility, prevRes},
               {res},
               [c, prevTex, target, file, hasHistory, m, prelude] {
                 ProgramSpec spec{"view " + file,
                                  {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, file}},
                                  prelude};
                 Program& p = c.shaders->get(spec);
                 if (!p.valid()) return;
                 Framebuffer fb("view target");
                 fb.attach({target}, nullptr);
                 fb.bind();
                 glViewport(0, 0, target->width(), target->height());
                 p.use();
                 TextureUnits units;
                 bindInputs(c, p, units, prevTex, true);
                 setAccumulationUniforms(p, c.view, c.prevProj, hasHistory, m);
                 drawFullscreenTriangle();
               }});
    graph.requestSink(res);
  }
}

// Switches that change the shader's work are defines, not uniform branches (llvmpipe pays for
// both sides of a branch).
std::string pixelCorrectDefines(const ParamSet& params, bool writeRaw, bool keepBest) {
  std::string d;
  if (writeRaw) d += "#define PC_WRITE_RAW\n";
  if (params.choice("pc.history_filter") == "catmull-rom") d += "#define PC_CATMULL_ROM\n";
  if (params.b("pc.reject_neighbours")) d += "#define PC_REJECT_NEIGHBOURS\n";
  if (keepBest) d += "#define PC_KEEP_BEST\n";
  if (params.b("pc.area_light")) d += "#define PC_AREA_LIGHT\n";
  return d;
}

}  // namespace

// The update pass's targets: colour, the history written this frame, the raw test when wanted.
Framebuffer* PixelCorrectState::updateFramebuffer(int write, const AccumulationContext& ctx, Texture2D* rawTarget) {
  if (fboRaw_[write] != rawTarget || fboColor_[write] != ctx.colorTex || !fbo_[write].id()) {
    fbo_[write] = Framebuffer("pixel-correct update");
    std::vector<const Texture2D*> targets = {ctx.colorTex, history_[write].get()};
    if (rawTarget) targets.push_back(rawTarget);
    fbo_[write].attach(targets, ctx.depthTex);
    fboRaw_[write] = rawTarget;
    fboColor_[write] = ctx.colorTex;
  }
  return &fbo_[write];
}

void PixelCorrectState::commit(const FrameUpdate& u) {
  adaptive_ = u.adaptive;
  keepBest_ = u.keepBest;
  showingTest_ = u.showingTest;
  m_ = u.m;
  current_ = u.write;
  hasHistory_ = true;
  ++frames_;
  if (u.advanceJitter) ++jitterIndex_;
}

AccumulationOutput PixelCorrectState::addPasses(FrameGraph& graph, const AccumulationContext& ctx) {
  const ParamSet& params = *ctx.params;
  const GLenum format = params.choice("pc.history_format") == "fp32" ? GL_RGBA32F : GL_RGBA16F;
  ensureHistory(ctx.width, ctx.height, format);
  // pc.while_moving = test: while the camera moves show this frame's test (no history read); the
  // history restarts from it at rest, like after a cut.
  FrameUpdate u;
  u.showingTest = ctx.cameraMoved && plainTestWhileMoving(params);
  u.adaptive = params.b("pc.adaptive");
  u.keepBest = params.b("pc.keep_best");
  u.advanceJitter = !params.b("pc.pause_jitter");
  u.m = pixelCorrectNextExponent(params, m_, ctx.cameraMoved, hasHistory_ && !u.showingTest);
  const int read = current_;
  u.write = 1 - current_;
  const bool hasHistory = hasHistory_ && !u.showingTest;
  const std::string tag = ctx.viewportTag;
  const std::string prevRes = "pc.history.prev" + tag, nextRes = "pc.history" + tag;
  graph.importResource(prevRes);
  const AccumulationContext c = ctx;  // passes run after this returns: keep a copy
  Texture2D* prevTex = history_[read].get();
  // The raw test is a render target of its own: written only when a view or a readback wants it.
  bool writeRaw = graph.requested(ctx.rawVisibility);
  for (const std::string& name : views())
    writeRaw = writeRaw || (ctx.viewTargets.count(name) && ctx.viewTargets.at(name));
  Texture2D* rawTarget = writeRaw ? ctx.rawVisibilityTarget : nullptr;
  Framebuffer* fbo = updateFramebuffer(u.write, ctx, rawTarget);
  const std::string prelude = ctx.techniquePrelude + pixelCorrectDefines(params, writeRaw, u.keepBest);

  // One scene pass, as in the paper: test, reprojection, update and shading with multiple
  // render targets; the previous-frame position comes from the vertex shader.
  graph.add({"pixel-correct" + tag,
             {ctx.shadowMap, prevRes},
             writeRaw ? std::vector<std::string>{ctx.color, ctx.finalVisibility, nextRes, ctx.rawVisibility}
                      : std::vector<std::string>{ctx.color, ctx.finalVisibility, nextRes},
             [this, c, prevTex, fbo, hasHistory, u, prelude, writeRaw] {
               ProgramSpec spec{
                   "pixel-correct",
                   {{GL_VERTEX_SHADER, "passes/gbuffer.vert"}, {GL_FRAGMENT_SHADER, "accumulation/pixel_correct.frag"}},
                   prelude};
               fbo->bind();
               glViewport(0, 0, c.width, c.height);
               // Background: lit (s = 1) with no history (depth 0); raw test lit with no confidence.
               const float history[4] = {1, 0, 0, 0}, raw[4] = {1, 0, 0, 0};
               glClearNamedFramebufferfv(fbo->id(), GL_COLOR, 1, history);
               if (writeRaw) glClearNamedFramebufferfv(fbo->id(), GL_COLOR, 2, raw);
               glClearNamedFramebufferfi(fbo->id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
               c.drawScene(spec, [&](const Program& p, TextureUnits& units) {
                 bindInputs(c, p, units, prevTex, false);
                 setAccumulationUniforms(p, c.view, c.prevProj, hasHistory, u.m);
               });
               c.drawSky();
               commit(u);
             }});
  addPixelCorrectViews(graph, c, views(), prevTex, prelude, hasHistory, u.m);
  // The shown visibility is the history's R channel (s(n)): no separate target to write.
  return {ctx.finalVisibility, history_[u.write].get(), ctx.color, ctx.depthTex};
}

namespace {

// The update weight: the confidence exponent m, fixed or adaptive, and what the update keeps.
std::vector<ParamDecl> exponentParams() {
  return {
      {.key = "pc.m",
       .type = ParamType::Float,
       .min = 1,
       .max = 30,
       .defaultValue = 15,
       .help = "confidence exponent m (w = conf^m, eq. 6): high = slow, noise-free, pixel-exact; low = fast, noisy"},
      {.key = "pc.adaptive",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "adaptive m: pc.m_moving while the camera moves, then + pc.m_step per still frame up to pc.m (after a "
               "cut: pc.m with pc.warmup, else pc.m_moving)"},
      {.key = "pc.m_moving",
       .type = ParamType::Float,
       .min = 1,
       .max = 30,
       .defaultValue = 3,
       .help = "exponent m while the camera moves (adaptive; also after a cut without pc.warmup)"},
      {.key = "pc.m_step",
       .type = ParamType::Float,
       .min = 0,
       .max = 2,
       .defaultValue = 0.1,
       .unit = "per frame",
       .help = "increase of m per still frame (adaptive)"},
      {.key = "pc.warmup",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "beyond the paper: update weight w / (W + w) with W the pixel's accumulated weight (capped at 1, and "
               "shrunk when the history is interpolated between texels), a confidence-weighted mean; off = eq. 2"},
      {.key = "pc.keep_best",
       .type = ParamType::Bool,
       .defaultValue = 0,
       .help = "beyond the paper, the m -> infinity limit of eq. 6: a test replaces the history only when it is more "
               "confident than the best test the history holds (whose weight shrinks when the history is resampled); "
               "off = eq. 2 (pc.warmup off) or the confidence-weighted mean (pc.warmup on)"},
  };
}

// The jitter of the layout's window per frame (and of the light point for the area light).
std::vector<ParamDecl> jitterParams() {
  return {
      {.key = "pc.jitter",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "sub-texel translation of the light window, Halton(2,3) per frame"},
      {.key = "pc.jitter_moving",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "jitter (and rotate) while the camera moves, as the paper does; off = the layout's own stable "
               "rasterization while moving (no jitter noise, no refinement until the camera rests)"},
      {.key = "pc.while_moving",
       .type = ParamType::Enum,
       .defaultValue = 0,
       .help = "accumulate (the paper): the history keeps accumulating jittered tests while the camera moves; test "
               "(beyond the paper): show the layout's own unjittered test while moving and accumulate only at rest",
       .choices = {"accumulate", "test"}},
      {.key = "pc.jitter_amplitude",
       .type = ParamType::Float,
       .min = 0,
       .max = 2,
       .defaultValue = 1,
       .unit = "texels",
       .help = "translation range: offsets in [-0.5,0.5] x amplitude texels"},
      {.key = "pc.rotate",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "in-plane rotation of the light window, Halton(5) per frame (translation alone repeats edge patterns)"},
      {.key = "pc.rotation_deg",
       .type = ParamType::Float,
       .min = 0,
       .max = 45,
       .defaultValue = 10,
       .unit = "degrees",
       .help = "rotation range: angles in [-a, a]"},
      {.key = "pc.area_light",
       .type = ParamType::Bool,
       .defaultValue = 0,
       .help = "beyond the paper (its future work): each frame's map is seen from another point of the area light "
               "(Halton over the disk) and the history is the plain mean of the last pc.area_frames tests, which "
               "converges to the area light's visibility (no effect on the light when light.radius is 0)"},
      {.key = "pc.area_frames",
       .type = ParamType::Int,
       .min = 2,
       .max = 1024,
       .defaultValue = 256,
       .unit = "frames",
       .help = "with pc.area_light: the mean's memory (the update weight never drops below 1/this)",
       .logScale = true},
      {.key = "pc.pause_jitter",
       .type = ParamType::Bool,
       .defaultValue = 0,
       .help = "keep the current jitter (the history still updates); render one frame to single-step"},
  };
}

// How the history is read back, stored and rejected where the scene moved.
std::vector<ParamDecl> historyParams() {
  return {
      {.key = "pc.disocclusion",
       .type = ParamType::Float,
       .min = 0.001,
       .max = 0.5,
       .defaultValue = 0.02,
       .unit = "relative depth",
       .help = "history tap rejected when |expected - stored view depth| > this x expected depth",
       .logScale = true},
      {.key = "pc.history_filter",
       .type = ParamType::Enum,
       .defaultValue = 0,
       .help = "history resampling: bilinear (the paper) blurs edges a little more every frame while the camera "
               "moves; catmull-rom (beyond the paper) keeps them sharper, clamped to the bilinear footprint's range "
               "(no ringing)",
       .choices = {"bilinear", "catmull-rom"}},
      {.key = "pc.history_format",
       .type = ParamType::Enum,
       .defaultValue = 0,
       .help = "history buffer precision (s, depth, W): fp16 as in the paper, or fp32",
       .choices = {"fp16", "fp32"}},
      {.key = "pc.reject",
       .type = ParamType::Float,
       .min = 0,
       .max = 1,
       .defaultValue = 0.05,
       .unit = "visibility",
       .help = "moving casters (beyond the paper): history replaced by the current test when they differ by more "
               "than this and the test is unambiguous (confident, or its whole neighbourhood agrees); 1 = off"},
      {.key = "pc.reject_confidence",
       .type = ParamType::Float,
       .min = 0,
       .max = 1,
       .defaultValue = 0.9,
       .help = "confidence above which a disagreeing test replaces the history (with pc.reject)"},
      {.key = "pc.reject_neighbours",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "a disagreeing test also replaces the history when the map gives the same answer one texel around the "
               "receiver in every direction (no jitter could change it: the caster moved) (with pc.reject)"},
  };
}

class PixelCorrectAccumulation : public Accumulation {
 public:
  std::string id() const override { return "pixel-correct"; }
  std::string help() const override {
    return "screen-space history with confidence-weighted updates and jittered shadow maps (Scherzer, Jeschke, "
           "Wimmer 2007): shadow edges converge to pixel-correct over ~10-60 still frames";
  }
  std::vector<ParamDecl> params() const override {
    std::vector<ParamDecl> all = exponentParams();
    for (auto&& group : {jitterParams(), historyParams()}) all.insert(all.end(), group.begin(), group.end());
    return all;
  }
  std::unique_ptr<AccumulationState> createState() const override { return std::make_unique<PixelCorrectState>(); }
};

}  // namespace

void registerPixelCorrect(std::vector<std::unique_ptr<Accumulation>>& out) {
  out.push_back(std::make_unique<PixelCorrectAccumulation>());
}

}  // namespace sl
