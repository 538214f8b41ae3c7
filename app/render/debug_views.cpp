// The common debug views. Each is a pass that writes view.<name>[v]; the frame graph culls the
// ones nobody shows.
#include "render/gpu_scene.h"
#include "render/renderer.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace sl {

namespace {

void addBox(std::vector<float>& out, const std::vector<glm::vec3>& c, const glm::vec3& color) {
  // Corner index bits: x = 1, y = 2, z = 4; the 12 edges join corners differing in one bit.
  for (int a = 0; a < 8; ++a)
    for (int bit = 1; bit < 8; bit <<= 1) {
      int b = a | bit;
      if (b == a) continue;
      for (int idx : {a, b}) out.insert(out.end(), {c[idx].x, c[idx].y, c[idx].z, color.r, color.g, color.b});
    }
}

// The world corners of a view's clip cube. `undividedY`: the view's clip y is not divided by w
// (LogPSM: y is the linear coordinate its log maps, and the log fixes -1 and 1), so a corner is
// the world point with clip (x w, y, z w, w): inv (x w, y, z w, w) = w a + y b, w fixed by a
// homogeneous coordinate of 1.
std::vector<glm::vec3> unprojectCube(const glm::mat4& viewProj, float nearZ, float farZ, bool undividedY = false) {
  glm::mat4 inv = glm::inverse(viewProj);
  std::vector<glm::vec3> out;
  for (int i = 0; i < 8; ++i) {
    const float x = i & 1 ? 1.0f : -1.0f, y = i & 2 ? 1.0f : -1.0f, z = i & 4 ? farZ : nearZ;
    if (undividedY) {
      const glm::vec4 a = inv * glm::vec4(x, 0.0f, z, 1.0f), b = inv * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f);
      const float w = (1.0f - y * b.w) / a.w;
      out.emplace_back(w * glm::vec3(a) + y * glm::vec3(b));
      continue;
    }
    glm::vec4 p = inv * glm::vec4(x, y, z, 1.0f);
    out.emplace_back(glm::vec3(p) / p.w);
  }
  return out;
}

}  // namespace

// The light-space overview: the scene from above and behind, the camera frustum and every light
// view's frustum as lines (the `lightspace` view).
void Renderer::drawLightSpaceOverview(const Viewport& vp, Texture2D& view, Texture2D& depth, const FrameInput& in) {
  Texture2D* target = &view;
  ProgramSpec sceneSpec{
      "view overview", {{GL_VERTEX_SHADER, "views/overview.vert"}, {GL_FRAGMENT_SHADER, "views/overview.frag"}}, ""};
  ProgramSpec lineSpec{"view lines",
                       {{GL_VERTEX_SHADER, "views/lines.vert"},
                        {GL_GEOMETRY_SHADER, "views/lines.geom"},
                        {GL_FRAGMENT_SHADER, "views/lines.frag"}},
                       ""};
  Program& lp = shaders_.get(lineSpec);
  if (!lp.valid()) return;
  Framebuffer fbo("view.lightspace");
  fbo.attach({target}, &depth);
  fbo.bind();
  const float bg[4] = {0.12f, 0.13f, 0.16f, 1.0f};
  glClearNamedFramebufferfv(fbo.id(), GL_COLOR, 0, bg);
  glClearNamedFramebufferfi(fbo.id(), GL_DEPTH_STENCIL, 0, 1.0f, 0);
  // An overview camera above and behind the scene sees both frusta.
  Bounds b = scene_->boundsAt(in.time);
  float radius = glm::length(b.extent()) * 0.5f + 1e-3f;
  glm::vec3 center = b.center();
  glm::vec3 eye = center + glm::normalize(glm::vec3(0.7f, 1.2f, 0.9f)) * radius * 2.2f;
  glm::mat4 overview = glm::perspective(glm::radians(45.0f), float(target->width()) / float(target->height()),
                                        radius * 0.05f, radius * 6.0f) *
                       glm::lookAt(eye, center, glm::vec3(0, 1, 0));
  glEnable(GL_DEPTH_TEST);
  PassPrograms programs(shaders_, sceneSpec, [this, &overview](const Program& p, TextureUnits&) {
    p.set("u_viewProj", overview);
    p.set("u_lightDirection", scene_->light.direction);
  });
  gpu_->draw(programs, in.time, in.time);
  std::vector<float> lines;
  // The camera frustum, cut at the scene's extent so that it stays readable.
  Camera cut = in.camera;
  cut.farPlane = std::min(cut.farPlane, glm::length(in.camera.position - center) + radius);
  glm::mat4 camProj = cameraProjection(cut, float(in.width) / float(in.height));
  // Yellow, or white beside partitioned views (whose second colour is yellow).
  const bool partitioned = vp.lightSpace.views.size() > 1;
  addBox(lines, unprojectCube(camProj * view_, -1.0f, 1.0f),
         partitioned ? glm::vec3(1.0f) : glm::vec3(1.0f, 0.85f, 0.1f));
  // One light view in cyan; the views of a partitioned layout in the colours of the
  // `cascades` view (shaders/views/cascades.frag), nearest split first.
  static const glm::vec3 palette[8] = {{0.90f, 0.30f, 0.25f}, {0.95f, 0.75f, 0.20f}, {0.35f, 0.75f, 0.30f},
                                       {0.25f, 0.55f, 0.90f}, {0.65f, 0.40f, 0.85f}, {0.30f, 0.80f, 0.80f},
                                       {0.90f, 0.55f, 0.70f}, {0.60f, 0.60f, 0.60f}};
  const auto& views = vp.lightSpace.views;
  for (size_t i = 0; i < views.size(); ++i)
    addBox(lines, unprojectCube(views[i].viewProj, -1.0f, 1.0f, views[i].logDelta > 0.0f),
           views.size() == 1 ? glm::vec3(0.2f, 0.9f, 1.0f) : palette[i % 8]);
  glNamedBufferSubData(linesVbo_, 0, static_cast<GLsizeiptr>(std::min<size_t>(lines.size(), 4096) * sizeof(float)),
                       lines.data());
  lp.use();
  lp.set("u_viewProj", overview);
  // Lines that stay visible when the view is minified (a thumbnail, a projector): 1/300 of the
  // target's height, at least 1.5 pixels.
  lp.set("u_targetSize", glm::vec2(target->width(), target->height()));
  lp.set("u_lineWidth", std::max(1.5f, float(target->height()) / 300.0f));
  glDisable(GL_DEPTH_TEST);
  glBindVertexArray(linesVao_);
  glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(lines.size() / 6));
  glBindVertexArray(0);
}

void Renderer::addDebugViewPasses(FrameGraph& g, Viewport& vp, const std::string& tag, const FrameInput& in) {
  const std::string prelude = techniquePrelude(vp);
  const std::string sm = vp.shadowResource_;
  const std::string visibility = vp.output_.visibility;
  const Texture2D* visTex = vp.visibilityTexture();

  auto fullscreenView = [&](const std::string& name, const std::string& frag, std::vector<std::string> reads,
                            bool needsTechnique, const std::string& vert = "passes/fullscreen.vert") {
    if (!vp.views_.count(name)) return;
    const std::string modules = needsTechnique ? prelude : "";
    Texture2D* target = vp.views_[name].get();
    g.add({"view." + name + tag,
           reads,
           {"view." + name + tag},
           [this, &vp, target, frag, vert, modules, visTex, needsTechnique] {
             ProgramSpec spec{"view " + frag, {{GL_VERTEX_SHADER, vert}, {GL_FRAGMENT_SHADER, frag}}, modules};
             Program& p = shaders_.get(spec);
             if (!p.valid()) return;
             Framebuffer fbo("view target");
             fbo.attach({target}, nullptr);
             fbo.bind();
             p.use();
             TextureUnits units;
             if (needsTechnique)
               bindTechnique(p, units, vp);
             else
               setTechniqueUniforms(p, vp.frameParams_, vp.lightSpace, scene_->light);
             bindGBuffer(p, units, visTex);
             // The raw depth of each layer (also under compare representations: the view shows it).
             units.bind(p, "u_shadowDepth", vp.representation->depthTexture()->id());
             p.set("u_viewSize", glm::vec2(target->width(), target->height()));
             drawFullscreen();
           }});
    g.requestSink("view." + name + tag);
  };
  fullscreenView("shadowmap", "views/shadowmap.frag", {sm}, false, "views/shadowmap.vert");
  fullscreenView("texels", "views/texels.frag", {"gbuffer"}, true);
  fullscreenView("aliasing", "views/aliasing.frag", {"gbuffer"}, true);
  fullscreenView("visibility", "views/visibility.frag", {"gbuffer", visibility}, false);

  if (vp.views_.count("lightspace")) {
    Texture2D* target = vp.views_["lightspace"].get();
    // Its depth buffer is the graph's (it was a new texture every frame).
    const std::string depth = "view.lightspace.depth" + tag;
    g.createTexture(depth, {GL_DEPTH_COMPONENT32F, target->width(), target->height()});
    g.add({"view.lightspace" + tag, {}, {"view.lightspace" + tag, depth}, [this, &vp, target, &in, &g, depth] {
             drawLightSpaceOverview(vp, *target, transientTexture(g, depth), in);
           }});
    g.requestSink("view.lightspace" + tag);
  }
}

}  // namespace sl
