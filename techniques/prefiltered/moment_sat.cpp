// Summed-area tables of the moment targets (Crow 1984; Hensley et al. 2005 for shadow maps):
// each 32-bit target becomes the table of its moments minus an offset, over the texels that
// visible receivers' lookups can read (satCover). Three compute passes per layer: the offset
// (the mean of the moments, read back), the rows (the moments taken from the shadow pass's depth
// and summed), the columns (every target in place). Any box is then four lookups, whatever its
// width (shaders/representations/prefiltered/moment_maps.glsl, SL_MOMENT_SAT).
#include "gl/shader_library.h"
#include "gl/storage_blocks.h"
#include "gl/texture_units.h"
#include "prefiltered/moment_state.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sl {

namespace {

// The mean pass reads every kMeanStride-th row: the offset only has to be near the mean.
constexpr int kMeanStride = 4;

std::string targetFormats(const std::vector<Texture2D>& targets) {
  std::string d;
  for (size_t t = 0; t < targets.size(); ++t)
    d += "#define SL_SAT_FORMAT" + std::to_string(t) + " " + imageFormatName(targets[t].format()) + "\n";
  return d;
}

void bindTargets(const Program& p, const std::vector<Texture2D>& targets, GLenum access) {
  for (size_t t = 0; t < targets.size(); ++t) {
    glBindImageTexture(static_cast<GLuint>(t), targets[t].id(), 0, GL_TRUE, 0, access, targets[t].format());
    p.set("u_table" + std::to_string(t), static_cast<int>(t));
  }
}

void unbindTargets(size_t count) {
  for (size_t t = 0; t < count; ++t)
    glBindImageTexture(static_cast<GLuint>(t), 0, 0, GL_FALSE, 0, GL_READ_ONLY, GL_R32F);
}

GLuint groupsOf(int lines) { return static_cast<GLuint>((lines + 63) / 64); }

// The rows and columns any span reaches, (x0, y0, x1, y1); (0, 0, 0, 0) when none has a texel.
glm::ivec4 boundsOf(const std::vector<glm::ivec2>& spans) {
  glm::ivec4 r(1 << 30, 1 << 30, -1, -1);
  for (int y = 0; y < static_cast<int>(spans.size()); ++y) {
    const glm::ivec2 s = spans[static_cast<size_t>(y)];
    if (s.x > s.y) continue;
    r = glm::ivec4(std::min(r.x, s.x), std::min(r.y, y), std::max(r.z, s.y), std::max(r.w, y));
  }
  return r.z < 0 ? glm::ivec4(0) : r;
}

}  // namespace

MomentMapState::SatCover MomentMapState::satCover(const std::vector<glm::vec2>* hull, int layer) const {
  const int n = depth_.width();
  SatCover c;
  if (hull && !hull->empty()) {  // an empty hull is an unknown one (LightView::receiverHull)
    // A box of up to `reach` texels either side of a receiver, read bilinearly at its corners
    // (a corner at P reads the texels whose centres lie within one texel of P - 1).
    const float reach =
        layer < static_cast<int>(viewReach_.size()) ? viewReach_[static_cast<size_t>(layer)] : satReach_;
    c.rows = blurSpans(*hull, n, 1, std::ceil(reach) + kLookupReach + 1.0f);
  }
  std::optional<std::vector<glm::ivec2>> columns;
  if (!c.rows.empty()) columns = columnIntervals(c.rows, n);
  if (!columns) {  // every texel (or, were the spans no convex region's, every texel of their rectangle)
    const glm::ivec4 r = c.rows.empty() ? glm::ivec4(0, 0, n - 1, n - 1) : boundsOf(c.rows);
    c.rows.assign(static_cast<size_t>(n), glm::ivec2(1, 0));
    for (int y = r.y; y <= r.w; ++y) c.rows[static_cast<size_t>(y)] = {r.x, r.z};
    columns = columnIntervals(c.rows, n);
  }
  c.columns = *columns;
  c.rect = boundsOf(c.rows);
  return c;
}

void MomentMapState::upload(GLuint buffer, const std::vector<glm::ivec2>& data) {
  glNamedBufferData(buffer, static_cast<GLsizeiptr>(data.size() * sizeof(glm::ivec2)), data.data(), GL_STREAM_DRAW);
}

// The mean of the finite moments of every target over the spans (every kMeanStride-th row, every
// layer): the offset each table subtracts, summed and divided on the GPU into the SatOffsets
// buffer that the rows pass and the lookups read (nothing read back: until 2026-12-07 the row
// sums were, a stall of the frame on a GPU).
void MomentMapState::satOffsets(ShaderLibrary& shaders, const TechniqueBinder& bindTechnique,
                                const std::vector<SatCover>& covers) {
  const size_t targets = static_cast<size_t>(config_.targets());
  ensureSatBuffers(targets, covers.size());
  const glm::vec4 zero(0.0f);  // what the lookups add when a program below does not build
  glClearNamedBufferData(satBuffers_.offsets, GL_RGBA32F, GL_RGBA, GL_FLOAT, &zero);
  Program& p = shaders.get({"moment table mean",
                            {{GL_COMPUTE_SHADER, "passes/moment_sat_mean.comp"}},
                            defines() + "#include \"" + module_ + "\"\n"});
  Program& offsets = shaders.get({"moment table offsets",
                                  {{GL_COMPUTE_SHADER, "passes/moment_sat_offset.comp"}},
                                  "#define SL_MOMENT_TARGETS " + std::to_string(targets) + "\n"});
  if (!p.valid() || !offsets.valid()) return;
  p.use();
  TextureUnits units;
  bindTechnique(p, units);  // what representationMoments reads
  units.bind(p, "u_depth", depth_.id());
  p.set("u_meanStride", kMeanStride);
  bindStorage("RowSums", satBuffers_.rowSums);
  bindStorage("RowCounts", satBuffers_.rowCounts);
  int rows = 0;
  for (size_t l = 0; l < covers.size(); ++l) {
    const int sampled = (covers[l].rect.w - covers[l].rect.y) / kMeanStride + 1;
    upload(spans_, covers[l].rows);
    p.set("u_rect", covers[l].rect);
    p.set("u_layer", static_cast<int>(l));
    p.set("u_rowBase", rows);
    glDispatchCompute(groupsOf(sampled), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    rows += sampled;
  }
  offsets.use();
  offsets.set("u_rows", rows);
  bindStorage("SatOffsets", satBuffers_.offsets);
  glDispatchCompute(static_cast<GLuint>(targets), 1, 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// Row sums for every sampled row of every layer (at most n / kMeanStride + 1 each), and the
// offsets; kept between frames.
void MomentMapState::ensureSatBuffers(size_t targets, size_t layers) {
  const size_t rows = static_cast<size_t>(depth_.width() / kMeanStride + 1) * std::max<size_t>(layers, 1);
  const GLsizeiptr rowBytes = static_cast<GLsizeiptr>(rows * targets * sizeof(glm::vec4));
  if (satBuffers_.rowSums && satBuffers_.rowBytes == rowBytes && satBuffers_.targets == targets) return;
  satBuffers_.release();
  for (GLuint* b : {&satBuffers_.rowSums, &satBuffers_.rowCounts, &satBuffers_.offsets}) glCreateBuffers(1, b);
  glNamedBufferStorage(satBuffers_.rowSums, rowBytes, nullptr, 0);
  glNamedBufferStorage(satBuffers_.rowCounts, rowBytes, nullptr, 0);
  glNamedBufferStorage(satBuffers_.offsets, static_cast<GLsizeiptr>(targets * sizeof(glm::vec4)), nullptr, 0);
  label(GL_BUFFER, satBuffers_.rowSums, "moment table row sums");
  label(GL_BUFFER, satBuffers_.rowCounts, "moment table row counts");
  label(GL_BUFFER, satBuffers_.offsets, "moment table offsets");
  satBuffers_.rowBytes = rowBytes;
  satBuffers_.targets = targets;
}

glm::vec4 MomentMapState::satOffsetOf(int t) const {
  glm::vec4 v(0.0f);
  if (satBuffers_.offsets && t >= 0 && static_cast<size_t>(t) < satBuffers_.targets)
    glGetNamedBufferSubData(satBuffers_.offsets, static_cast<GLintptr>(t * sizeof(glm::vec4)), sizeof v, &v);
  return v;
}

double MomentMapState::buildSat(ShaderLibrary& shaders, const TechniqueBinder& bindTechnique,
                                const std::vector<std::vector<glm::vec2>>& hulls, bool wholeMap) {
  const int n = depth_.width();
  const int layers = std::max(depth_.layers(), 1);
  const bool skip = skipUnread_ && !wholeMap && static_cast<int>(hulls.size()) >= layers;
  std::vector<SatCover> covers;
  long long covered = 0;
  for (int l = 0; l < layers; ++l) {
    covers.push_back(satCover(skip ? &hulls[static_cast<size_t>(l)] : nullptr, l));
    for (const glm::ivec2 s : covers.back().rows) covered += std::max(0, s.y - s.x + 1);
  }
  // Lookups clamp their corners to the texels the tables cover: the union of the layers' rects.
  satRect_ = covers.front().rect;
  for (const SatCover& c : covers)
    satRect_ = glm::ivec4(std::min(satRect_.x, c.rect.x), std::min(satRect_.y, c.rect.y),
                          std::max(satRect_.z, c.rect.z), std::max(satRect_.w, c.rect.w));
  for (GLuint* b : {&spans_, &columns_})
    if (!*b) glCreateBuffers(1, b);
  bindStorage("SatSpans", spans_);
  bindStorage("SatColumns", columns_);
  satOffsets(shaders, bindTechnique, covers);
  const std::string formats = targetFormats(moments_);
  Program& rows = shaders.get({"moment table rows",
                               {{GL_COMPUTE_SHADER, "passes/moment_sat_rows.comp"}},
                               defines() + "#include \"" + module_ + "\"\n" + formats});
  Program& columns = shaders.get({"moment table columns",
                                  {{GL_COMPUTE_SHADER, "passes/moment_sat_columns.comp"}},
                                  "#define SL_MOMENT_TARGETS " + std::to_string(config_.targets()) + "\n" + formats});
  if (!rows.valid() || !columns.valid()) return 1.0;
  bindStorage("SatOffsets", satBuffers_.offsets);  // what the rows pass subtracts (satOffsets)
  for (int l = 0; l < layers; ++l) {
    const SatCover& cover = covers[static_cast<size_t>(l)];
    upload(spans_, cover.rows);
    upload(columns_, cover.columns);
    rows.use();
    TextureUnits units;
    bindTechnique(rows, units);
    units.bind(rows, "u_depth", depth_.id());
    rows.set("u_rect", cover.rect);
    rows.set("u_layer", l);
    bindTargets(rows, moments_, GL_WRITE_ONLY);
    glDispatchCompute(groupsOf(cover.rect.w - cover.rect.y + 1), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
    columns.use();
    columns.set("u_rect", cover.rect);
    columns.set("u_layer", l);
    bindTargets(columns, moments_, GL_READ_WRITE);
    glDispatchCompute(groupsOf(cover.rect.z - cover.rect.x + 1), 1, 1);
    glMemoryBarrier(GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
  }
  unbindTargets(moments_.size());
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  return static_cast<double>(covered) / (static_cast<double>(n) * n * layers);
}

}  // namespace sl
