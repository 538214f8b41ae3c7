#include "adaptive/depth_bend.h"

#include "gl/shader_library.h"
#include "gl/storage_blocks.h"
#include "gl/texture_units.h"

#include <algorithm>

namespace sl {

VirtualDepthBend::~VirtualDepthBend() {
  if (tileList_) glDeleteBuffers(1, &tileList_);
}

void VirtualDepthBend::tilesDrawn(const std::vector<int>& tiles) {
  for (int t : tiles) {
    if (t < 0) continue;
    if (static_cast<size_t>(t) >= stale_.size()) stale_.resize(static_cast<size_t>(t) + 1, 0);
    stale_[static_cast<size_t>(t)] = 1;
  }
}

GLuint VirtualDepthBend::update(ShaderLibrary& shaders, const Texture2D* depth, int page, int poolSide,
                                const std::string& defines) {
  if (!depth || depth->width() < page * poolSide || depth->height() < page * poolSide) return 0;
  // Made at the first marking with an atlas, or again when the atlas's size changes (it follows
  // virtual.pool and virtual.page, whose change re-tiles the pool: every page is drawn again).
  // Either way only tiles drawn since hold pages, and those are marked (tilesDrawn).
  if (!bend_ || bend_.width() != depth->width() || bend_.height() != depth->height())
    bend_ = Texture2D(GL_R32F, depth->width(), depth->height(), "virtual depth bend (3x3 second difference)");
  std::vector<int> tiles;
  const size_t poolTiles = static_cast<size_t>(poolSide) * static_cast<size_t>(poolSide);
  for (size_t t = 0; t < std::min(stale_.size(), poolTiles); ++t)
    if (stale_[t]) tiles.push_back(static_cast<int>(t));
  if (tiles.empty()) return bend_.id();
  Program& p = shaders.get({"virtual depth bend", {{GL_COMPUTE_SHADER, "passes/virtual_depth_bend.comp"}}, defines});
  if (!p.valid()) return 0;
  if (!tileList_) {
    glCreateBuffers(1, &tileList_);
    label(GL_BUFFER, tileList_, "virtual depth bend tiles");
  }
  glNamedBufferData(tileList_, static_cast<GLsizeiptr>(tiles.size() * sizeof(int)), tiles.data(), GL_STREAM_DRAW);
  p.use();
  TextureUnits units;
  units.bind(p, "u_virtualDepthAtlas", depth->id());
  bindStorage("BendTiles", tileList_);
  glBindImageTexture(0, bend_.id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  p.set("u_virtualDepthBend", 0);
  const GLuint groups = static_cast<GLuint>((page + 15) / 16);
  glDispatchCompute(groups, groups, static_cast<GLuint>(tiles.size()));
  glBindImageTexture(0, 0, 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_R32F);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT);
  std::fill(stale_.begin(), stale_.end(), 0);
  return bend_.id();
}

}  // namespace sl
