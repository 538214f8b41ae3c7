#include "reconstruction/silhouette_state.h"
#include "part/part_view.h"

#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "part/frame_graph.h"

namespace sl {

SilhouetteMapState::~SilhouetteMapState() {
  if (vbo_) glDeleteBuffers(1, &vbo_);
  if (vao_) glDeleteVertexArrays(1, &vao_);
}

void SilhouetteMapState::prepare(int size, int layers, int /*views*/) {
  depth_.prepare(size, layers, layers);
  if (points_ && points_.width() == size && points_.layers() == layers) return;
  points_ = Texture2D::array(GL_RG16F, size, size, layers, 1, "silhouette map");
  fbos_.clear();
  for (int l = 0; l < layers; ++l) {
    fbos_.emplace_back("silhouette map layer " + std::to_string(l));
    fbos_.back().attachLayer({&points_}, nullptr, l);
  }
}

void SilhouetteMapState::upload(const std::vector<glm::vec3>& segments) {
  if (!vao_) {
    glCreateVertexArrays(1, &vao_);
    glCreateBuffers(1, &vbo_);
    glVertexArrayVertexBuffer(vao_, 0, vbo_, 0, sizeof(glm::vec3));
    glVertexArrayAttribFormat(vao_, 0, 3, GL_FLOAT, GL_FALSE, 0);
    glVertexArrayAttribBinding(vao_, 0, 0);
    glEnableVertexArrayAttrib(vao_, 0);
    label(GL_VERTEX_ARRAY, vao_, "silhouette edges");
  }
  // A buffer is never empty: glNamedBufferData with size 0 is allowed, but keep one segment's room.
  const size_t bytes = std::max<size_t>(segments.size(), 2) * sizeof(glm::vec3);
  glNamedBufferData(vbo_, static_cast<GLsizeiptr>(bytes), nullptr, GL_DYNAMIC_DRAW);
  if (!segments.empty())
    glNamedBufferSubData(vbo_, 0, static_cast<GLsizeiptr>(segments.size() * sizeof(glm::vec3)), segments.data());
  segments_ = segments.size() / 2;
}

void SilhouetteMapState::drawSilhouettes(const PartContext& ctx) {
  const std::vector<glm::vec3>& segments = edges_.update(*ctx.scene, ctx.shadowedLight(), ctx.time);
  if (edges_.changed() || !vao_) upload(segments);
  const ProgramSpec spec{"silhouette edges",
                         {{GL_VERTEX_SHADER, "representations/silhouette_edges.vert"},
                          {GL_GEOMETRY_SHADER, "representations/silhouette_edges.geom"},
                          {GL_FRAGMENT_SHADER, "representations/silhouette_edges.frag"}},
                         ctx.techniquePrelude};
  Program& p = ctx.shaders->get(spec);
  const float none[4] = {-1.0f, -1.0f, 0.0f, 0.0f};
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  const LightSpace& space = *ctx.lightSpace;
  std::vector<bool> cleared(fbos_.size(), false);
  for (size_t view = 0; view < space.views.size(); ++view) {
    // Views packed into one layer (LightSpace::layerOf) draw into it in turn, cleared once.
    const size_t layer = static_cast<size_t>(space.layerOf(view));
    if (layer >= fbos_.size()) continue;
    fbos_[layer].bind();
    glViewport(0, 0, points_.width(), points_.height());
    if (!cleared[layer]) glClearNamedFramebufferfv(fbos_[layer].id(), GL_COLOR, 0, none);
    cleared[layer] = true;
    if (!p.valid() || segments_ == 0) continue;
    p.use();
    TextureUnits units;
    ctx.bindTechnique(p, units);  // depth map (u_shadowMap), light views, parameters
    p.set("u_shadowView", static_cast<int>(view));
    p.set("u_silSize", static_cast<float>(points_.width()));
    // A view in an atlas keeps to its square (LightView::atlasRect), as in the shadow pass.
    const glm::ivec4& rect = space.views[view].atlasRect;
    if (rect.z > 0) {
      glEnable(GL_SCISSOR_TEST);
      glScissor(rect.x, rect.y, rect.z, rect.w);
    }
    glBindVertexArray(vao_);
    glDrawArrays(GL_LINES, 0, static_cast<GLsizei>(2 * segments_));
    glDisable(GL_SCISSOR_TEST);
  }
  glBindVertexArray(0);
}

std::string SilhouetteMapState::addPasses(FrameGraph& graph, const PartContext& ctx) {
  const std::string out = "silhouette" + ctx.viewportTag;
  graph.add({"silhouette" + ctx.viewportTag, {ctx.shadowMap}, {out}, [this, ctx] { drawSilhouettes(ctx); }});
  auto it = ctx.viewTargets.find("silhouette-points");
  if (it != ctx.viewTargets.end() && it->second) {
    Texture2D* target = it->second;
    const std::string res = "view.silhouette-points" + ctx.viewportTag;
    graph.add({res, {out}, {res}, [ctx, target] { drawPartView(ctx, target, "views/silhouette_points.frag"); }});
    graph.requestSink(res);
  }
  return out;
}

void SilhouetteMapState::bind(const Program& p, TextureUnits& units) const {
  depth_.bind(p, units);
  // Only programs that read the points get them: the silhouette pass renders into them.
  if (glGetUniformLocation(p.id(), "u_silhouetteMap") >= 0) units.bind(p, "u_silhouetteMap", points_.id());
}

std::string SilhouetteMapState::status() const { return std::to_string(segments_) + " silhouette edges"; }

}  // namespace sl
