// Forward shadow mapping (Zhang 1998): instead of looking the map up from every eye pixel
// (backward), every light-view sample is sent forward into the eye view and lights the eye
// pixels it covers that show the same surface. Pixels no sample reaches stay dark: the holes of
// forward mapping where one light texel spans more than a splat of eye pixels.
//
// As an accumulation: the renderer's shadow pass makes the light view (depth map); the G-buffer
// is the eye view's depth buffer. A splat (forward.splat pixels, or its texel's footprint with
// forward.grow) lights only pixels whose surface falls in its own texel, so by default one
// compute pass finds the lit pixels per eye pixel, from the splats of the texels its surface
// falls in (the gather); forward.scatter runs Zhang's order instead, every light texel sent into
// the eye view and the pixels of its splat tested, splats of many pixels drawn as rectangles by
// the rasterizer: the same image (a test compares them pixel for pixel), four to five times the
// work at 1280x720. Either writes the visibility target.
// The renderer's visibility test (the backward nearest test) runs only for the `forward-holes`
// view, which compares the two; the deferred shade pass lights the G-buffer with the splats.
#include "reconstruction/reconstruction.h"

#include "gl/gl_util.h"
#include "gl/storage_blocks.h"
#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "part/frame_graph.h"
#include "part/uniforms.h"

#include <glm/gtc/matrix_inverse.hpp>

namespace sl {

namespace {

class ForwardState : public AccumulationState {
 public:
  ~ForwardState() override {
    if (vao_) glDeleteVertexArrays(1, &vao_);
    if (large_) glDeleteBuffers(1, &large_);
    if (mapToClip_) glDeleteBuffers(1, &mapToClip_);
  }
  std::vector<std::string> views() const override { return {"forward-holes"}; }
  AccumulationOutput addPasses(FrameGraph& graph, const AccumulationContext& ctx) override;
  std::string status() const override {
    return std::to_string(points_) +
           (scattered_ ? " light samples splatted" : " light samples, their splats gathered per pixel");
  }

 private:
  void splat(const AccumulationContext& c);
  void ensureLargeSplats();
  void ensureReceivers(int width, int height);
  static void setSplatUniforms(const AccumulationContext& c, const Program& p, int mapSize);
  void gather(const AccumulationContext& c, const std::string& prelude, int mapSize);
  void scatter(const AccumulationContext& c, const std::string& prelude, int mapSize);
  void prepareReceivers(const AccumulationContext& c, Program& receivers, int mapSize);
  void drawLargeSplats(const AccumulationContext& c, Program& quads);
  // Large splats (accumulation/forward_large.glsl: a count and the draw's command in 32 bytes,
  // then 16 bytes a splat): 4 MB; a splat that does not fit is tested in the texel pass.
  static constexpr int kLargeCapacity = 1 << 18;
  // Each eye pixel's receiver record for the scatter (accumulation/forward_receivers.comp), RGBA32F.
  std::unique_ptr<Texture2D> receivers_;
  // The matrices from a texel's sample to the eye's clip space (accumulation/forward_splat.glsl,
  // MapToClip: two mat4 and three vec4), written as a storage block and read as uniform block 2.
  static constexpr GLsizeiptr kMapToClipBytes = 2 * 64 + 3 * 16;
  static constexpr GLuint kMapToClipBinding = 2;
  GLuint vao_ = 0;
  GLuint large_ = 0;
  GLuint mapToClip_ = 0;
  long long points_ = 0;
  bool scattered_ = false;  // the last frame ran Zhang's scatter (forward.scatter)
};

void ForwardState::ensureLargeSplats() {
  if (large_) return;
  glCreateBuffers(1, &large_);
  glNamedBufferData(large_, 32 + GLsizeiptr(kLargeCapacity) * 16, nullptr, GL_DYNAMIC_DRAW);
  label(GL_BUFFER, large_, "forward large splats");
}

void ForwardState::ensureReceivers(int width, int height) {
  if (receivers_ && receivers_->width() == width && receivers_->height() == height) return;
  receivers_ = std::make_unique<Texture2D>(GL_RGBA32F, width, height, "forward receivers");
}

// The lit pixels, from every light texel's splat: gathered per eye pixel (the default), or
// scattered per texel as Zhang does (forward.scatter). Either way the visibility target starts
// dark: a pixel no splat lights stays unlit.
void ForwardState::splat(const AccumulationContext& c) {
  const float dark[4] = {0.0f, 1.0f, 0.0f, 0.0f};
  glClearTexImage(c.finalVisibilityTex->id(), 0, GL_RG, GL_FLOAT, dark);
  const std::string prelude = "#define SL_DEFERRED\n#define SL_REPRESENTATION_IN_COMPUTE\n" + c.techniquePrelude;
  Program& mapToClip =
      c.shaders->get({"forward map to clip", {{GL_COMPUTE_SHADER, "accumulation/forward_map_to_clip.comp"}}, prelude});
  if (!mapToClip.valid()) return;
  if (!mapToClip_) {
    glCreateBuffers(1, &mapToClip_);
    glNamedBufferData(mapToClip_, kMapToClipBytes, nullptr, GL_DYNAMIC_DRAW);
    label(GL_BUFFER, mapToClip_, "forward map to clip");
  }
  const int size = static_cast<int>(c.params->i("shadowmap.size"));
  mapToClip.use();
  TextureUnits units;
  c.bindTechniqueInputs(mapToClip, units);  // the light views
  mapToClip.set("u_eyeViewProj", c.proj * c.view);
  mapToClip.set("u_mapSize", size);
  bindStorage("ForwardMapToClipOut", mapToClip_);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_UNIFORM_BARRIER_BIT);
  glBindBufferBase(GL_UNIFORM_BUFFER, kMapToClipBinding, mapToClip_);
  glBindImageTexture(0, c.finalVisibilityTex->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RG16F);
  scattered_ = c.params->b("forward.scatter");
  if (scattered_)
    scatter(c, prelude, size);
  else
    gather(c, prelude, size);
  points_ = static_cast<long long>(size) * size;
}

void ForwardState::setSplatUniforms(const AccumulationContext& c, const Program& p, int mapSize) {
  p.set("u_mapSize", mapSize);
  p.set("u_screenSize", glm::vec2(c.width, c.height));
  p.set("u_visibilityOut", 0);  // image unit (the layout binding says the same)
}

// One invocation per eye pixel: lit when the splat of a texel its surface point falls in covers
// it (accumulation/forward_gather.comp).
void ForwardState::gather(const AccumulationContext& c, const std::string& prelude, int mapSize) {
  Program& pixels =
      c.shaders->get({"forward gather", {{GL_COMPUTE_SHADER, "accumulation/forward_gather.comp"}}, prelude});
  if (!pixels.valid()) return;
  pixels.use();
  TextureUnits units;
  c.bindTechniqueInputs(pixels, units);  // depth map, light views, G-buffer, parameters
  setSplatUniforms(c, pixels, mapSize);
  glDispatchCompute(static_cast<GLuint>((c.width + 7) / 8), static_cast<GLuint>((c.height + 7) / 8), 1);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

// One invocation per light texel (accumulation/forward_splat.comp) after the receivers pass;
// small splats are tested in the texel pass, large ones (more than kInlinePixels pixels)
// appended and drawn as rectangles, one instance each, sized on the GPU: no read-back.
void ForwardState::scatter(const AccumulationContext& c, const std::string& prelude, int mapSize) {
  Program& texels =
      c.shaders->get({"forward splat", {{GL_COMPUTE_SHADER, "accumulation/forward_splat.comp"}}, prelude});
  Program& args =
      c.shaders->get({"forward splat args", {{GL_COMPUTE_SHADER, "accumulation/forward_splat_args.comp"}}, ""});
  Program& receivers =
      c.shaders->get({"forward receivers", {{GL_COMPUTE_SHADER, "accumulation/forward_receivers.comp"}}, prelude});
  Program& quads = c.shaders->get({"forward splat quads",
                                   {{GL_VERTEX_SHADER, "accumulation/forward_splat_quad.vert"},
                                    {GL_FRAGMENT_SHADER, "accumulation/forward_splat_quad.frag"}},
                                   prelude});
  if (!texels.valid() || !args.valid() || !quads.valid() || !receivers.valid()) return;
  ensureLargeSplats();
  const GLuint zero = 0;
  glNamedBufferSubData(large_, 0, sizeof(zero), &zero);
  bindStorage("ForwardLargeSplats", large_);
  prepareReceivers(c, receivers, mapSize);
  texels.use();
  TextureUnits units;
  c.bindTechniqueInputs(texels, units);  // depth map, light views, G-buffer, parameters
  units.bind(texels, "u_forwardReceivers", receivers_->id());
  setSplatUniforms(c, texels, mapSize);
  texels.set("u_largeCapacity", kLargeCapacity);
  const GLuint groups = static_cast<GLuint>((mapSize + 7) / 8);
  glDispatchCompute(groups, groups, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  args.use();
  args.set("u_largeCapacity", kLargeCapacity);
  glDispatchCompute(1, 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT | GL_FRAMEBUFFER_BARRIER_BIT);
  drawLargeSplats(c, quads);
}

// Each eye pixel's receiver record, once (accumulation/forward_receivers.comp); pixels outside
// the light view's map are lit there, as the backward test has them: no texel can reach them.
void ForwardState::prepareReceivers(const AccumulationContext& c, Program& receivers, int mapSize) {
  ensureReceivers(c.width, c.height);
  glBindImageTexture(1, receivers_->id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
  receivers.use();
  TextureUnits units;
  c.bindTechniqueInputs(receivers, units);
  setSplatUniforms(c, receivers, mapSize);
  receivers.set("u_receiversOut", 1);
  glDispatchCompute(static_cast<GLuint>((c.width + 7) / 8), static_cast<GLuint>((c.height + 7) / 8), 1);
  glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT | GL_TEXTURE_FETCH_BARRIER_BIT);
}

void ForwardState::drawLargeSplats(const AccumulationContext& c, Program& quads) {
  Framebuffer fbo("forward large splats");
  fbo.attach({c.finalVisibilityTex}, nullptr);
  fbo.bind();
  glViewport(0, 0, c.width, c.height);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  quads.use();
  TextureUnits units;
  c.bindTechniqueInputs(quads, units);
  units.bind(quads, "u_forwardReceivers", receivers_->id());
  quads.set("u_mapSize", static_cast<int>(c.params->i("shadowmap.size")));
  quads.set("u_screenSize", glm::vec2(c.width, c.height));
  glBindVertexArray(vao_);
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, large_);
  glDrawArraysIndirect(GL_TRIANGLES, reinterpret_cast<const void*>(4));  // forwardLargeDraw, after the count
  glBindBuffer(GL_DRAW_INDIRECT_BUFFER, 0);
  glBindVertexArray(0);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

AccumulationOutput ForwardState::addPasses(FrameGraph& graph, const AccumulationContext& ctx) {
  if (!vao_) {
    glCreateVertexArrays(1, &vao_);  // attribute-less: the vertex shader reads the map by gl_VertexID
    label(GL_VERTEX_ARRAY, vao_, "forward splats");
  }
  // The backward test, for the forward-holes view alone (culled when nothing shows it).
  ctx.addVisibilityTest();
  const AccumulationContext c = ctx;
  graph.add(
      {"forward-splat" + ctx.viewportTag, {"gbuffer", ctx.shadowMap}, {ctx.finalVisibility}, [this, c] { splat(c); }});
  auto it = ctx.viewTargets.find("forward-holes");
  if (it != ctx.viewTargets.end() && it->second) {
    Texture2D* target = it->second;
    const std::string res = "view.forward-holes" + ctx.viewportTag;
    graph.add({res, {"gbuffer", ctx.finalVisibility, ctx.rawVisibility}, {res}, [this, c, target] {
                 ProgramSpec spec{"view forward holes",
                                  {{GL_VERTEX_SHADER, "passes/fullscreen.vert"},
                                   {GL_FRAGMENT_SHADER, "accumulation/views_forward_holes.frag"}},
                                  ""};
                 Program& p = c.shaders->get(spec);
                 if (!p.valid()) return;
                 Framebuffer fb("view target");
                 fb.attach({target}, nullptr);
                 fb.bind();
                 glViewport(0, 0, target->width(), target->height());
                 p.use();
                 TextureUnits units;
                 units.bind(p, "u_forward", c.finalVisibilityTex->id());
                 units.bind(p, "u_backward", c.rawVisibilityTex->id());
                 units.bind(p, "u_gPosition", c.gPosition->id());
                 // The context has no fullscreen helper: one triangle from the attribute-less VAO.
                 glBindVertexArray(vao_);
                 glDrawArrays(GL_TRIANGLES, 0, 3);
                 glBindVertexArray(0);
               }});
    graph.requestSink(res);
  }
  return ctx.addDeferredShade(ctx.finalVisibility, ctx.finalVisibilityTex);
}

class ForwardAccumulation : public Accumulation {
 public:
  std::string id() const override { return "forward"; }
  std::string help() const override {
    return "forward shadow mapping (Zhang 1998): light-view samples splatted into the eye view (holes where they "
           "do not cover)";
  }
  std::vector<ParamDecl> params() const override {
    return {{.key = "forward.splat",
             .type = ParamType::Float,
             .min = 1,
             .max = 16,
             .defaultValue = 4,
             .unit = "pixels",
             .help = "side of the square each light sample lights in the eye view (Zhang's fixed splat, with "
                     "forward.grow off; grown splats are at least a pixel)"},
            {.key = "forward.grow",
             .type = ParamType::Bool,
             .defaultValue = 1,
             .help = "beyond the paper: each splat grows to its light texel's footprint in the eye view (up to 255 "
                     "pixels), so a texel stretched over many pixels (grazing light) leaves no holes; off: Zhang's "
                     "fixed forward.splat and the holes the paper shows"},
            {.key = "forward.scatter",
             .type = ParamType::Bool,
             .defaultValue = 0,
             .help = "Zhang's scatter: every light texel sent into the eye view and the pixels of its splat tested "
                     "one by one; off: the same lit pixels found per eye pixel, from the splats of the texels its "
                     "surface falls in (beyond the paper; the same image, one invocation per pixel instead of per "
                     "texel)"},
            {.key = "forward.footprint",
             .type = ParamType::Float,
             .min = 1,
             .max = 4,
             .defaultValue = 1,
             .unit = "texels",
             .help = "a sample lights only eye pixels whose surface falls within this many light texels of it "
                     "(1: its own texel), so a splat does not spread light across a shadow edge"}};
  }
  std::unique_ptr<AccumulationState> createState() const override { return std::make_unique<ForwardState>(); }
};

}  // namespace

void registerForwardAccumulation(std::vector<std::unique_ptr<Accumulation>>& out) {
  out.push_back(std::make_unique<ForwardAccumulation>());
}

}  // namespace sl
