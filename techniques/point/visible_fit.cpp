#include "point/visible_fit.h"

#include "gl/gl_util.h"
#include "gl/shader_library.h"
#include "gl/storage_blocks.h"
#include "gl/texture_units.h"
#include "part/contexts.h"

#include <cmath>

namespace sl {

namespace {

constexpr int kMaxViews = 6;  // passes/point_face_bounds.comp

}  // namespace

ParamDecl fitVisibleParam() {
  return {.key = "point.fit_visible",
          .type = ParamType::Bool,
          .defaultValue = 0,
          .help =
              "fit each face (each hemisphere, with paraboloid.fit) to the pixels the camera sees in it, each axis "
              "on its own, from a GPU min/max reduction of the G-buffer before the shadow pass (SDSM per face, "
              "beyond the papers); off: to the view frustum's part of the scene. A face no visible pixel reads is "
              "not drawn"};
}

std::vector<glm::vec3> pixelBoundsCorners(const ViewPixelBounds& b, const glm::mat4& view, int size) {
  const glm::vec2 extent = b.hi - b.lo;
  const float pad = std::max(extent.x, extent.y) * (0.02f + 4.0f / float(std::max(size, 16))) + 1e-6f;
  const glm::vec2 lo = b.lo - pad, hi = b.hi + pad;
  const glm::mat4 toWorld = glm::inverse(view);
  std::vector<glm::vec3> out;
  for (float z : {b.nearest, b.farthest})
    for (int c = 0; c < 4; ++c) {
      const glm::vec2 t(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y);
      out.emplace_back(toWorld * glm::vec4(t * z, -z, 1.0f));
    }
  return out;
}

ViewPixelReduction::ViewPixelReduction() {
  glCreateBuffers(1, &buffer_);
  glNamedBufferData(buffer_, kMaxViews * 6 * sizeof(uint32_t), nullptr, GL_DYNAMIC_READ);
  label(GL_BUFFER, buffer_, "point face bounds");
}

ViewPixelReduction::~ViewPixelReduction() { glDeleteBuffers(1, &buffer_); }

std::vector<ViewPixelBounds> ViewPixelReduction::reduce(const PartContext& ctx, const LightSpace& space,
                                                        const Light& light) {
  const int count = std::min(static_cast<int>(space.views.size()), kMaxViews);
  Program& p = ctx.shaders->get({"point face bounds", {{GL_COMPUTE_SHADER, "passes/point_face_bounds.comp"}}, ""});
  if (!p.valid() || count == 0) return {};  // no program (a shader error shown): the frustum fit stays
  std::vector<ViewPixelBounds> out(static_cast<size_t>(count));
  uint32_t raw[kMaxViews * 6];
  for (int i = 0; i < kMaxViews * 6; ++i) raw[i] = (i & 1) == 0 ? ~0u : 0u;
  glNamedBufferSubData(buffer_, 0, sizeof(raw), raw);
  p.use();
  TextureUnits units;
  ctx.bindGBuffer(p, units);
  p.set("u_viewCount", count);
  p.set("u_paraboloid", space.views[0].projection == LightView::Projection::Paraboloid ? 1 : 0);
  p.set("u_lightPos", glm::vec3(glm::inverse(space.views[0].view)[3]));
  p.set("u_lightRange", light.range > 0.0f ? light.range : 1e30f);
  for (int v = 0; v < count; ++v) p.set("u_faceView[" + std::to_string(v) + "]", space.views[size_t(v)].view);
  bindStorage("PointFaceBounds", buffer_);
  glDispatchCompute((ctx.width + 127) / 128, (ctx.height + 127) / 128, 1);  // 8x8 invocations of 16x16 pixels
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT | GL_SHADER_STORAGE_BARRIER_BIT);
  glGetNamedBufferSubData(buffer_, 0, sizeof(raw), raw);
  for (int v = 0; v < count; ++v) {
    float f[6];
    for (int k = 0; k < 6; ++k) f[k] = floatFromOrderedBits(raw[v * 6 + k]);
    ViewPixelBounds& b = out[size_t(v)];
    b.valid = f[0] <= f[1] && f[2] <= f[3] && f[4] <= f[5] && std::isfinite(f[0]) && std::isfinite(f[1]) &&
              std::isfinite(f[2]) && std::isfinite(f[3]) && std::isfinite(f[5]);
    b.lo = {f[0], f[2]};
    b.hi = {f[1], f[3]};
    b.nearest = f[4];
    b.farthest = f[5];
  }
  return out;
}

}  // namespace sl
