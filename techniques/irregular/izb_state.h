// Per-viewport state of the irregular z-buffer: the eye samples of the G-buffer binned into a
// light-space grid (count, prefix sum, scatter: one index buffer), every caster triangle tested
// exactly against the samples listed under the cells it covers, one shadow bit per sample.
// It keeps the depth map of DepthMapState as the fallback for samples that did not fit.
#pragma once

#include "gl/readback_ring.h"
#include "part/depth_map_state.h"

#include <cstdint>
#include <memory>
#include <string>

namespace sl {

// The scene's triangles in world space for the tests (positions, own id, material, uvs) and
// the alpha of masked materials' textures, rebuilt when the scene or its time changes.
struct IzbSceneBuffers {
  ~IzbSceneBuffers();
  void update(const Scene& scene, double time);
  GLuint triangles = 0, instanceBase = 0, materials = 0, alpha = 0;
  uint32_t triangleCount = 0;
  long long bytes = 0;
  bool anyMasked = false;  // a material is alpha-masked: the triangles pass looks its alpha up

 private:
  const Scene* scene_ = nullptr;
  double time_ = -1.0;
  size_t signature_ = 0;
};

// Under a sun (toLight: the direction to it), the matrix of a view's grid: the view's own with
// the direction's clip image moved to depth alone, so that a sample's whole ray to the sun
// projects onto its own cell, where its occluders are tested. False when the view's matrix is
// not already so up to rounding (a relative 1e-3): a warp along the light (a camera-space PSM in
// general), whose grid would be another one than the view shows.
bool sunGridMatrix(const glm::mat4& viewProj, const glm::vec3& toLight, glm::mat4& grid);

class IzbState : public DepthMapState {
 public:
  IzbState();
  ~IzbState() override;
  void configure(const ParamSet& params) override;
  std::string addPasses(FrameGraph& graph, const PartContext& ctx) override;
  void bind(const Program& p, TextureUnits& units) const override;
  std::vector<std::string> views() const override { return {"izb-lists"}; }
  std::string status() const override;
  long long texels() const override;
  // Samples of the last frame that did not fit in the lists (waiting for its counters).
  uint32_t overflowCount() const { return counter(0); }
  uint32_t listedCount() const { return counter(1); }  // samples binned into the grid (fitting or not)

 private:
  void ensureBuffers(int width, int height, int grid);
  void runLists(const PartContext& ctx);
  void listView(const PartContext& ctx, int view);
  void runTriangles(const PartContext& ctx);
  void drawListView(const PartContext& ctx, Texture2D* target);
  void setCommon(const Program& p, const PartContext& ctx) const;
  // izb_common.glsl: IzbCounters of the last frame (waiting for its copy).
  uint32_t counter(int index) const;

  IzbSceneBuffers scene_;
  // counts[cells], offsets[cells + 1], blockSums, pixelCell[pixels], rank[pixels], samples[pixels],
  // list[capacity], bits[pixels / 32] (shadowed), fallback[pixels / 32], counters (overflowed,
  // listed, queued chunks, the listed samples' clip w range), the queue of triangles'
  // chunks and its indirect dispatch
  GLuint counts_ = 0, offsets_ = 0, blockSums_ = 0, pixelCell_ = 0, rank_ = 0, samples_ = 0, list_ = 0, bits_ = 0,
         fallback_ = 0, counters_ = 0, queue_ = 0, dispatch_ = 0, cellState_ = 0;
  // The counters copied after each frame's tests and read when they have arrived: the status
  // line makes the CPU wait for no frame (mutable: reading an arrived copy changes nothing shown).
  mutable std::unique_ptr<ReadbackRing> counterCopies_;
  int width_ = 0, height_ = 0, grid_ = 0;
  int views_ = 1;  // light views of this frame, listed and tested one after another
  long long capacity_ = 0;
  int gridParam_ = 512;
  double capacityPct_ = 100.0;
  std::string error_;  // why the lists are not built (views no matrix places points in), shown as status
  std::vector<glm::mat4> gridViewProjs_;  // each view's grid (listableViews)
  glm::mat4 gridViewProj_{1.0f};          // the grid of the view being listed and tested
};

}  // namespace sl
