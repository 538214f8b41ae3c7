#include "irregular/izb_state.h"
#include "gl/storage_blocks.h"

#include "gl/texture_units.h"
#include "part/frame_graph.h"
#include "part/uniforms.h"

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

constexpr long long kQueueCapacity = 1 << 20;  // rows of triangles that list samples

// A sample's bytes at most (izb_common.glsl): its ray (two vec4 under a light with a position)
// and its cell and triangle.
constexpr long long kSampleBytes = 32, kPixelCellBytes = 8;
constexpr size_t kCounterBytes = 6 * sizeof(uint32_t);  // what status reads of IzbCounters (32 bytes)

void resize(GLuint& buffer, long long bytes, const char* name) {
  if (buffer) glDeleteBuffers(1, &buffer);
  glCreateBuffers(1, &buffer);
  glNamedBufferData(buffer, static_cast<GLsizeiptr>(std::max(bytes, 16LL)), nullptr, GL_DYNAMIC_DRAW);
  label(GL_BUFFER, buffer, name);
}

void clearBuffer(GLuint buffer) {
  const uint32_t zero = 0;
  glClearNamedBufferData(buffer, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
}

GLuint groups(long long n, int size) { return static_cast<GLuint>((n + size - 1) / size); }

// Conditions the passes' shaders compile in rather than test: llvmpipe runs the code of both
// sides of a branch whatever its lanes take (docs/performance.md).
std::string define(const char* name, bool on) { return std::string("#define ") + name + (on ? " 1\n" : " 0\n"); }

// IZB_W_RANGE: the listed samples' clip w range is kept and culls casters under a sun whose grid
// is a warp; an orthographic grid's w row is (0, 0, 0, 1) (sunGridMatrix keeps it), so w is 1
// at every point and the range culls nothing.
std::string gridDefines(const PartContext& ctx, const glm::mat4& grid) {
  const bool positional = ctx.shadowedLight().positional();
  const bool constantW = grid[0][3] == 0.0f && grid[1][3] == 0.0f && grid[2][3] == 0.0f && grid[3][3] == 1.0f;
  return define("IZB_POSITIONAL", positional) + define("IZB_W_RANGE", !positional && !constantW);
}

}  // namespace

// p + t d projects where p does for every t when M d has no x, y or w. The light view is
// orthographic along the light and a light-space warp (LiSPSM, TSM) has its perspective axis
// across it: both are so but for the rounding of their matrices' products (up to a relative
// 1.4e-6 in the layouts' views; izb_views_test.cpp), which the grid removes: M - (M d without
// its z) d^T / |d|^2 sends d to depth alone, and moves a point by that rounding only.
bool sunGridMatrix(const glm::mat4& viewProj, const glm::vec3& toLight, glm::mat4& grid) {
  const glm::dmat4 m(viewProj);
  const glm::dvec3 d(toLight);
  glm::dvec4 image = m * glm::dvec4(d, 0.0);
  double scale = 0.0;
  for (int column = 0; column < 3; ++column) scale = std::max(scale, glm::length(m[column]));
  const double off = std::max({std::abs(image.x), std::abs(image.y), std::abs(image.w)});
  if (!(off <= 1e-3 * scale) || !(glm::dot(d, d) > 0.0)) return false;
  image.z = 0.0;
  glm::dmat4 corrected = m;
  for (int column = 0; column < 3; ++column) corrected[column] -= image * (d[column] / glm::dot(d, d));
  grid = glm::mat4(corrected);
  return true;
}

IzbState::IzbState() : DepthMapState(false) {}

IzbState::~IzbState() {
  for (GLuint b : {counts_, offsets_, blockSums_, pixelCell_, rank_, samples_, list_, bits_, fallback_, counters_,
                   queue_, dispatch_, cellState_})
    if (b) glDeleteBuffers(1, &b);
}

void IzbState::configure(const ParamSet& params) {
  gridParam_ = params.i("izb.grid");
  capacityPct_ = params.get("izb.capacity");
}

void IzbState::ensureBuffers(int width, int height, int grid) {
  const long long pixels = static_cast<long long>(width) * height;
  const long long capacity = std::max(1LL, static_cast<long long>(std::floor(pixels * capacityPct_ / 100.0)));
  if (width != width_ || height != height_) {
    width_ = width;
    height_ = height;
    resize(pixelCell_, pixels * kPixelCellBytes, "izb pixel cell");
    resize(rank_, pixels * 4, "izb sample rank");
    resize(samples_, pixels * kSampleBytes, "izb samples");
    resize(bits_, (pixels + 31) / 32 * 4, "izb shadow bits");
    resize(fallback_, (pixels + 31) / 32 * 4, "izb fallback bits");
    if (!counters_) resize(counters_, 32, "izb counters");  // izb_common.glsl: IzbCounters
    // Two queues (izb_triangles.comp): rows of unmasked triangles, then of alpha-masked ones.
    if (!queue_) resize(queue_, 2 * kQueueCapacity * 8, "izb triangle-row queues");
    if (!dispatch_) resize(dispatch_, 24, "izb queue dispatches");
  }
  if (capacity != capacity_) {
    capacity_ = capacity;
    resize(list_, capacity * 4, "izb lists");
  }
  if (grid != grid_) {
    grid_ = grid;
    const long long cells = static_cast<long long>(grid) * grid;
    resize(counts_, cells * 4, "izb cell counts");
    resize(cellState_, cells * 16, "izb cell state");  // izb_common.glsl: IzbCellState
    resize(offsets_, (cells + 1) * 4, "izb cell offsets");
    resize(blockSums_, groups(cells, 1024) * 4, "izb block sums");
  }
}

namespace {

// Why the lists cannot be built over these views ("" when they can), and each view's grid
// matrix. Each view needs a grid its matrix alone places points in and that sends each sample's
// ray to the light onto the cell of its start: perspective from a light with a position (a spot,
// a point light's faces), or under a sun a view sunGridMatrix accepts (orthographic, LiSPSM,
// TSM). The log warp and the paraboloid are not matrices.
std::string listableViews(const LightSpace& ls, const Light& light, std::vector<glm::mat4>& grids) {
  grids.clear();
  for (const LightView& v : ls.views) {
    glm::mat4 grid = v.viewProj;
    const bool matrix = v.projection == LightView::Projection::Matrix;
    if (matrix && (light.positional() || sunGridMatrix(v.viewProj, -light.direction, grid))) {
      grids.push_back(grid);
      continue;
    }
    return "irregular z-buffer needs light views a matrix places points in (orthographic, a warp across the "
           "light, or perspective from a spot or point light); this layout gives " +
           std::to_string(ls.views.size()) +
           (v.projection == LightView::Projection::Paraboloid ? " paraboloid"
            : v.perspective                                   ? " warped"
                                                              : " log-warped") +
           " view(s): every pixel uses the shadow-map test";
  }
  return "";
}

// The sign of a grid view's depth (clip z / w) along a ray toward the light: a perspective view
// from a light's position has its depth fall toward the light, as every GL perspective does
// toward its eye; under a sun the rays keep their w (sunGridMatrix) and the direction's image
// has depth alone, whose sign it is.
float depthTowardLight(const glm::mat4& grid, const Light& light) {
  if (light.positional()) return -1.0f;
  return (grid * glm::vec4(-light.direction, 0.0f)).z < 0.0f ? -1.0f : 1.0f;
}

}  // namespace

std::string IzbState::addPasses(FrameGraph& graph, const PartContext& ctx) {
  const LightSpace& ls = *ctx.lightSpace;
  error_ = listableViews(ls, ctx.shadowedLight(), gridViewProjs_);  // a point light's one view is a spot's
  ensureBuffers(ctx.width, ctx.height, gridParam_);
  views_ = static_cast<int>(ls.views.size());
  gridViewProj_ = gridViewProjs_.empty() ? ls.primary().viewProj : gridViewProjs_.front();
  scene_.update(*ctx.scene, ctx.time);
  const std::string lists = "izb.lists" + ctx.viewportTag, out = "izb" + ctx.viewportTag;
  graph.add({lists, {"gbuffer"}, {lists}, [this, ctx] { runLists(ctx); }});
  // The shadow map stays an input: overflowed samples fall back to it.
  graph.add({"izb.triangles" + ctx.viewportTag, {lists, ctx.shadowMap}, {out}, [this, ctx] {
               runTriangles(ctx);
               // Several views: each view's lists, then its triangles, in turn (one set of buffers).
               for (int view = 1; view < views_ && error_.empty(); ++view) {
                 listView(ctx, view);
                 runTriangles(ctx);
               }
               if (!counterCopies_) counterCopies_ = std::make_unique<ReadbackRing>(kCounterBytes);
               counterCopies_->copyFrom(counters_);  // for the status line, read when it arrives
             }});
  auto it = ctx.viewTargets.find("izb-lists");
  if (it != ctx.viewTargets.end() && it->second) {
    const std::string view = "view.izb-lists" + ctx.viewportTag;
    Texture2D* target = it->second;
    graph.add({view, {lists}, {view}, [this, ctx, target] { drawListView(ctx, target); }});
    graph.requestSink(view);
  }
  return out;
}

void IzbState::setCommon(const Program& p, const PartContext& ctx) const {
  p.set("u_izbGrid", grid_);
  p.set("u_izbCapacity", static_cast<int>(std::min<long long>(capacity_, 0x7fffffff)));
  p.set("u_izbViewProj", gridViewProj_);
  p.set("u_izbDepthTowardLight", depthTowardLight(gridViewProj_, ctx.shadowedLight()));
  p.set("u_izbSize", glm::vec2(ctx.width, ctx.height));
  // The storage blocks of shaders/passes/izb_common.glsl, by name (gl/storage_blocks.h).
  for (auto [block, buffer] : {std::pair<const char*, GLuint>{"IzbTriangles", scene_.triangles},
                               {"IzbInstanceBase", scene_.instanceBase},
                               {"IzbMaterials", scene_.materials},
                               {"IzbAlpha", scene_.alpha},
                               {"IzbCounts", counts_},
                               {"IzbCellState", cellState_},
                               {"IzbOffsets", offsets_},
                               {"IzbBlockSums", blockSums_},
                               {"IzbPixelCell", pixelCell_},
                               {"IzbRank", rank_},
                               {"IzbSamples", samples_},
                               {"IzbList", list_},
                               {"IzbBits", bits_},
                               {"IzbFallback", fallback_},
                               {"IzbCounters", counters_},
                               {"IzbQueue", queue_},
                               {"IzbDispatch", dispatch_}})
    bindStorage(block, buffer);
}

// The frame's bits cleared, then the first view's lists. Under several views every fallback bit
// starts set: the count pass clears it for each pixel a view lists or decides
// (shaders/passes/izb_count.comp); without lists (error_) every sample keeps it.
void IzbState::runLists(const PartContext& ctx) {
  for (GLuint b : {bits_, fallback_, counters_}) clearBuffer(b);  // counts_: per view (listView)
  if (!error_.empty() || views_ > 1) {
    const uint32_t ones = ~0u;
    glClearNamedBufferData(fallback_, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &ones);
  }
  if (!error_.empty()) {
    clearBuffer(offsets_);  // no lists
    return;
  }
  listView(ctx, 0);
}

// Count, prefix sum and scatter: the samples of each light-space cell of `view`, contiguous in
// one buffer.
void IzbState::listView(const PartContext& ctx, int view) {
  gridViewProj_ = gridViewProjs_[size_t(view)];
  const long long cells = static_cast<long long>(grid_) * grid_;
  clearBuffer(counts_);
  clearBuffer(cellState_);
  // The queue of triangle rows is per view: its rows are cells of this view's grid.
  // So are the listed samples' w range (counters 3 and 4) and the masked rows' queue (5).
  const uint32_t zero = 0;
  glClearNamedBufferSubData(counters_, GL_R32UI, 8, 16, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
  ProgramSpec count{"izb count",
                    {{GL_COMPUTE_SHADER, "passes/izb_count.comp"}},
                    gridDefines(ctx, gridViewProj_) + define("IZB_SEVERAL_VIEWS", views_ > 1)};
  Program& pc = ctx.shaders->get(count);
  if (!pc.valid()) return;
  pc.use();
  TextureUnits units;
  ctx.bindGBuffer(pc, units);
  setLightUniforms(pc, ctx.shadowedLight());
  setCommon(pc, ctx);
  pc.set("u_izbInstances", static_cast<int>(ctx.scene->instances.size()));
  pc.set("u_izbTriangles", static_cast<int>(scene_.triangleCount));
  glDispatchCompute(groups(ctx.width, 8), groups(ctx.height, 8), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  for (int step = 1; step <= 3; ++step) {
    ProgramSpec scan{"izb scan " + std::to_string(step),
                     {{GL_COMPUTE_SHADER, "passes/izb_scan.comp"}},
                     "#define IZB_STEP " + std::to_string(step) + "\n"};
    Program& ps = ctx.shaders->get(scan);
    if (!ps.valid()) return;
    ps.use();
    setCommon(ps, ctx);
    ps.set("u_izbCells", static_cast<int>(cells));
    // One invocation per chunk of 1024 cells (izb_scan.comp), one for the chunks' totals.
    glDispatchCompute(step == 2 ? 1 : groups(groups(cells, 1024), 64), 1, 1);
    glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
  }
  ProgramSpec scatter{"izb scatter", {{GL_COMPUTE_SHADER, "passes/izb_scatter.comp"}}, ""};
  Program& ps = ctx.shaders->get(scatter);
  if (!ps.valid()) return;
  ps.use();
  setCommon(ps, ctx);
  glDispatchCompute(groups(ctx.width, 8), groups(ctx.height, 8), 1);
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

// Every caster triangle against the samples listed under it; then the bits are what the
// technique's module reads while shading.
void IzbState::runTriangles(const PartContext& ctx) {
  if (error_.empty() && scene_.triangleCount > 0) {
    // Step 3 once per queue: the rows of unmasked triangles with a program without the alpha
    // lookup, then, in a scene with masks, those of masked ones.
    for (int run = 1; run <= (scene_.anyMasked ? 4 : 3); ++run) {
      const int step = std::min(run, 3), queue = run - 3;
      const bool masked = step == 3 ? queue == 1 : scene_.anyMasked;
      ProgramSpec spec{"izb triangles " + std::to_string(step),
                       {{GL_COMPUTE_SHADER, "passes/izb_triangles.comp"}},
                       "#define IZB_STEP " + std::to_string(step) + "\n" + gridDefines(ctx, gridViewProj_) +
                           define("IZB_MASKED", masked) + define("IZB_QUEUE", queue == 1)};
      Program& p = ctx.shaders->get(spec);
      if (!p.valid()) return;
      p.use();
      setCommon(p, ctx);
      p.set("u_izbTriangles", static_cast<int>(scene_.triangleCount));
      p.set("u_izbQueueCapacity", static_cast<int>(kQueueCapacity));
      setLightUniforms(p, ctx.shadowedLight());
      if (step == 1) glDispatchCompute(groups(scene_.triangleCount, 64), 1, 1);
      if (step == 2) glDispatchCompute(1, 1, 1);
      if (step == 3) {
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, dispatch_);
        glDispatchComputeIndirect(static_cast<GLintptr>(queue * 3 * sizeof(uint32_t)));
        glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
      }
      glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_COMMAND_BARRIER_BIT);
    }
  }
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
}

void IzbState::drawListView(const PartContext& ctx, Texture2D* target) {
  ProgramSpec spec{"view izb lists",
                   {{GL_VERTEX_SHADER, "passes/fullscreen.vert"}, {GL_FRAGMENT_SHADER, "views/izb_lists.frag"}},
                   ""};
  Program& p = ctx.shaders->get(spec);
  if (!p.valid()) return;
  Framebuffer fbo("izb lists view");
  fbo.attach({target}, nullptr);
  fbo.bind();
  p.use();
  setCommon(p, ctx);
  ctx.drawFullscreen();
}

void IzbState::bind(const Program& p, TextureUnits& units) const {
  DepthMapState::bind(p, units);
  p.set("u_izbWidth", width_);
  bindStorage("IzbBits", bits_);
  bindStorage("IzbFallback", fallback_);
}

uint32_t IzbState::counter(int index) const {
  if (!counterCopies_) return 0;
  counterCopies_->finish();
  return counterCopies_->value<uint32_t>(static_cast<size_t>(index));
}

std::string IzbState::status() const {
  if (!error_.empty()) return error_;
  if (!counterCopies_) return "";
  // The newest counters that have arrived, without waiting for this frame's.
  counterCopies_->poll();
  if (!counterCopies_->ready()) return "counters of the first frame not read back yet";
  const auto counter = [this](size_t index) { return counterCopies_->value<uint32_t>(index); };
  const uint32_t overflow = counter(0), masked = counter(5);
  const bool several = views_ > 1;
  std::string s = std::to_string(counter(1)) +
                  (several ? " listings of samples in " + std::to_string(views_) + " views of " : " samples in ") +
                  std::to_string(grid_) + "² cells, " + std::to_string(counter(2) + masked) +
                  " rows of triangles queued (" + std::to_string(masked) + " alpha-masked)" +
                  (several ? " in the last" : "");
  if (overflow > 0)
    s += "; list capacity " + std::to_string(capacity_) + " overflowed: " + std::to_string(overflow) +
         " samples use the shadow-map test (raise izb.capacity)";
  return s;
}

// Texel equivalents: the depth map plus every buffer, one 32-bit word per texel.
long long IzbState::texels() const {
  const long long pixels = static_cast<long long>(width_) * height_;
  const long long cells = static_cast<long long>(grid_) * grid_;
  const long long words = cells * 2 + 1 + (cells + 1023) / 1024 + pixels * ((kPixelCellBytes + 4 + kSampleBytes) / 4) +
                          capacity_ + 2 * ((pixels + 31) / 32) + kQueueCapacity * 4 + scene_.bytes / 4;
  return DepthMapState::texels() + words;
}

}  // namespace sl
