// Summed-area tables of the moment targets (Crow 1984; Hensley et al. 2005 for shadow maps):
// after the shadow pass each 32-bit target becomes, in place, the table of its moments minus
// an offset, by a compute pass over rows and one over columns (shaders/passes/moment_sat.comp).
// Any box is then four lookups, whatever its width (shaders/representations/prefiltered/
// moment_maps.glsl, SL_MOMENT_SAT).
#include "gl/shader_library.h"
#include "gl/storage_blocks.h"
#include "prefiltered/moment_state.h"

#include <vector>

namespace sl {

namespace {

// The mean of the finite texels of every layer of `table`: the offset the table subtracts, so
// that its sums grow like a random walk instead of linearly with the texel count. Read back
// (a stall on a GPU; free on a software rasterizer, where every pass is synchronous).
glm::vec4 finiteMean(ShaderLibrary& shaders, const Texture2D& table, int layers) {
  const int size = table.width();
  const ProgramSpec spec{"moment table mean",
                         {{GL_COMPUTE_SHADER, "passes/moment_sat_mean.comp"}},
                         std::string("#define SL_SAT_FORMAT ") + imageFormatName(table.format()) + "\n"};
  Program& p = shaders.get(spec);
  if (!p.valid()) return glm::vec4(0.0f);
  GLuint buffers[2];
  glCreateBuffers(2, buffers);
  const GLsizeiptr bytes = static_cast<GLsizeiptr>(size) * 4 * sizeof(float);
  for (GLuint b : buffers) glNamedBufferData(b, bytes, nullptr, GL_STREAM_READ);
  bindStorage("RowSums", buffers[0]);
  bindStorage("RowCounts", buffers[1]);
  glBindImageTexture(0, table.id(), 0, GL_TRUE, 0, GL_READ_ONLY, table.format());
  p.use();
  p.set("u_size", size);
  glm::dvec4 sum(0.0), count(0.0);
  std::vector<glm::vec4> sums(static_cast<size_t>(size)), counts(static_cast<size_t>(size));
  for (int l = 0; l < layers; ++l) {
    p.set("u_layer", l);
    glDispatchCompute(static_cast<GLuint>((size + 63) / 64), 1, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(buffers[0], 0, bytes, sums.data());
    glGetNamedBufferSubData(buffers[1], 0, bytes, counts.data());
    for (int i = 0; i < size; ++i) {
      sum += glm::dvec4(sums[static_cast<size_t>(i)]);
      count += glm::dvec4(counts[static_cast<size_t>(i)]);
    }
  }
  glDeleteBuffers(2, buffers);
  return glm::vec4(sum / glm::max(count, glm::dvec4(1.0)));
}

}  // namespace

void MomentMapState::buildSat(ShaderLibrary& shaders) {
  const int layers = std::max(depth_.layers(), 1);
  const int size = depth_.width();
  satOffset_.assign(moments_.size(), glm::vec4(0.0f));
  for (size_t t = 0; t < moments_.size(); ++t) {
    const Texture2D& table = moments_[t];
    satOffset_[t] = finiteMean(shaders, table, layers);
    const ProgramSpec spec{"moment summed-area table",
                           {{GL_COMPUTE_SHADER, "passes/moment_sat.comp"}},
                           std::string("#define SL_SAT_FORMAT ") + imageFormatName(table.format()) + "\n"};
    Program& p = shaders.get(spec);
    if (!p.valid()) return;
    p.use();
    glBindImageTexture(0, table.id(), 0, GL_TRUE, 0, GL_READ_WRITE, table.format());
    p.set("u_size", size);
    p.set("u_offset", satOffset_[t]);
    for (int l = 0; l < layers; ++l) {
      p.set("u_layer", l);
      for (int vertical = 0; vertical < 2; ++vertical) {
        p.set("u_vertical", vertical);
        glDispatchCompute(static_cast<GLuint>((size + 63) / 64), 1, 1);
        glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
      }
    }
    glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_READ_WRITE, GL_R32F);
  }
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
}

}  // namespace sl
