#include "adaptive/virtual_layout.h"
#include "gl/storage_blocks.h"
#include "part/part_view.h"

#include "adaptive/depth_bend.h"
#include "adaptive/page_allocator.h"
#include "adaptive/quadtree_fit.h"
#include "gl/gl_util.h"
#include "gl/readback_ring.h"
#include "gl/shader_library.h"
#include "gl/texture_units.h"
#include "part/light_frame.h"
#include "part/frame_graph.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstring>
#include <iomanip>
#include <memory>
#include <sstream>

namespace sl {

VirtualSizes virtualSizes(const ParamSet& params) {
  VirtualSizes s;
  s.page = params.i("virtual.page");
  // Pages per side: the largest power of two that fits (a mip pyramid of pages halves exactly).
  const int wanted = std::max(params.i("virtual.size") / s.page, 1);
  s.pagesPerSide = 1;
  while (s.pagesPerSide * 2 <= wanted && s.pagesPerSide < 4096) s.pagesPerSide *= 2;
  s.virtualSize = s.pagesPerSide * s.page;
  // At most 255 x 255 tiles: a page-table entry holds tile + 1 in 16 bits (8192² of 32² pages).
  s.poolSide = std::clamp(params.i("virtual.pool") / s.page, 1, 255);
  s.atlasSize = s.poolSide * s.page;
  return s;
}

namespace {

const char* kViewNames[] = {"pages", "requested-resolution", "cache"};

// Per-viewport state: the page-marking pass, the allocation, the page table and the tiles the
// shadow pass draws.
class VirtualState : public LayoutState {
 public:
  explicit VirtualState(const Layout& layout) : LayoutState(layout) {}
  ~VirtualState() override {
    if (marks_) glDeleteBuffers(1, &marks_);
    if (grid_) glDeleteBuffers(1, &grid_);
    if (table_) glDeleteTextures(1, &table_);
  }
  // A cut or another scene: earlier frames' marks (virtual.async_marks) ask for pages of another view.
  void reset() override {
    pages_.invalidate();
    markCopies_.reset();
  }

  LightSpace compute(const LayoutInput& in) override {
    sizes_ = virtualSizes(*in.params);
    criterion_ = in.params->i("virtual.criterion");
    pages_.configure(sizes_.pagesPerSide, sizes_.poolSide * sizes_.poolSide);
    LayoutInput virt = in;
    LightSpace ls = layout_.compute(virt);
    ls.size = sizes_.atlasSize;
    // What the cached pages were drawn with: a change of the light view, scene or culling makes
    // every page stale; objects that moved only the pages under them, then and now.
    const bool changed = ls.primary().viewProj != drawnViewProj_ || in.scene != drawnScene_ ||
                         in.params->i("shadowmap.cull") != drawnCull_ || !in.params->b("virtual.cache");
    droppedByMotion_ = 0;
    if (changed)
      pages_.invalidate();
    else if (in.scene->hasMotion() && in.time != drawnTime_)
      droppedByMotion_ = invalidateMoved(*in.scene, ls.primary().viewProj, drawnTime_, in.time);
    drawnViewProj_ = ls.primary().viewProj;
    drawnScene_ = in.scene;
    drawnCull_ = in.params->i("shadowmap.cull");
    drawnTime_ = in.time;
    return ls;
  }

  std::string defines() const override {
    return "#define SL_VIRTUAL_PAGES " + std::to_string(sizes_.pagesPerSide) + "\n#define SL_VIRTUAL_LEVELS " +
           std::to_string(pages_.levels()) + "\n#define SL_VIRTUAL_PAGE " + std::to_string(sizes_.page) +
           "\n#define SL_VIRTUAL_POOL_SIDE " + std::to_string(sizes_.poolSide) + "\n#define SL_VIRTUAL_FIT_GRID " +
           std::to_string(fitGridSide(sizes_.pagesPerSide)) + "\n" + criterionDefines();
  }

  void bind(const Program& p, TextureUnits& units) const override {
    if (table_) units.bind(p, "u_pageTable", table_);
    p.set("u_pageTransform", glm::vec4(1.0f, 1.0f, 0.0f, 0.0f));
  }

  std::vector<std::string> views() const override { return {kViewNames[0], kViewNames[1], kViewNames[2]}; }

  std::string status() const override {
    std::ostringstream s;
    s << "virtual " << sizes_.virtualSize << "² in " << pages_.poolTiles() << " tiles of " << sizes_.page
      << "²: requested " << frame_.requested << ", resident " << frame_.resident << ", drawn " << draw_.size()
      << ", cache hits " << frame_.hits;
    if (droppedByMotion_ > 0) s << "; " << droppedByMotion_ << " dropped under moving objects";
    if (fitted_)
      s << "; quadtree fitted on the CPU: " << fit_.nodesVisited << " nodes, " << fit_.leaves
        << " leaves, finest level " << fit_.finestLevel << ", " << std::fixed << std::setprecision(2) << fitMs_
        << " ms";
    if (frame_.exhausted())
      s << "; pool exhausted: " << frame_.coarsened << " pages asked for served coarser, in " << frame_.coarsenedLevels
        << " level(s)";
    return s.str();
  }

  // The page table (a texel per page of level 0); the atlas is the representation's.
  long long texels() const override {
    return table_ ? static_cast<long long>(pages_.pagesPerSide()) * pages_.pagesPerSide() : 0;
  }

  std::vector<std::string> addPasses(FrameGraph& graph, const PartContext& ctx) override {
    ensureGpu();
    const std::string res = "virtual.pages" + ctx.viewportTag;
    // The marking reads world positions alone: the G-buffer pass then skips its other targets.
    graph.add({res, {"gbuffer.position"}, {res}, [this, ctx] { markAndAllocate(ctx); }});
    for (int v = 0; v < 3; ++v) addViewPass(graph, ctx, v, res);
    return {res};
  }

  // Its pages are tiles it places itself: never moved into a region of a shared atlas.
  bool drawsWholeViews() const override { return false; }
  // Every layer in tiles: the pages marked this frame, or every resident page when the
  // representation cleared the layer.
  void planShadowLayers(std::vector<ShadowLayerDraw>& layers, bool keepsLayers) override {
    if (!keepsLayers) {
      draw_.clear();
      for (int i = 0; i < pages_.flatSize(); ++i)
        if (pages_.tileOf(i) >= 0) draw_.push_back(i);
    }
    std::vector<int> drawnTiles;
    for (int page : draw_) drawnTiles.push_back(pages_.tileOf(page));
    bend_.tilesDrawn(drawnTiles);
    for (ShadowLayerDraw& layer : layers) {
      layer.tiled = true;
      layer.tiles.clear();
      for (size_t k = 0; k < draw_.size(); ++k) {
        const int t = drawnTiles[k];
        const int x = (t % sizes_.poolSide) * sizes_.page, y = (t / sizes_.poolSide) * sizes_.page;
        layer.tiles.push_back({glm::ivec4(x, y, sizes_.page, sizes_.page), pageTransform(static_cast<int>(k))});
      }
    }
  }

 private:
  // clip xy * .xy + w * .zw (shaders/layouts/virtual.glsl): the page's square onto [-1, 1]².
  glm::vec4 pageTransform(int tile) const {
    int level, x, y;
    pages_.decode(draw_[static_cast<size_t>(tile)], level, x, y);
    const float n = static_cast<float>(sizes_.pagesPerSide >> level);
    return glm::vec4(n, n, n - 2.0f * x - 1.0f, n - 2.0f * y - 1.0f);
  }
  void ensureGpu() {
    if (marks_ && tableSide_ == pages_.pagesPerSide()) return;  // the levels follow from the side
    if (marks_) glDeleteBuffers(1, &marks_);
    if (grid_) glDeleteBuffers(1, &grid_);
    if (table_) glDeleteTextures(1, &table_);
    glCreateBuffers(1, &marks_);
    glNamedBufferData(marks_, static_cast<GLsizeiptr>(pages_.flatSize() * sizeof(uint32_t)), nullptr, GL_DYNAMIC_READ);
    label(GL_BUFFER, marks_, "virtual page marks");
    glCreateBuffers(1, &grid_);
    glNamedBufferData(grid_, static_cast<GLsizeiptr>(fitGridValues() * sizeof(uint32_t)), nullptr, GL_DYNAMIC_READ);
    label(GL_BUFFER, grid_, "fitted virtual grid");
    glCreateTextures(GL_TEXTURE_2D, 1, &table_);
    glTextureStorage2D(table_, 1, GL_R32UI, pages_.pagesPerSide(), pages_.pagesPerSide());
    glTextureParameteri(table_, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(table_, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    label(GL_TEXTURE, table_, "virtual page table (finest resident page per level-0 page)");
    tableSide_ = pages_.pagesPerSide();
    uploadTable();
  }

  // What a lookup reads: per page of level 0 the finest resident page over it (its level in the
  // entry), so the shading fetches once instead of walking the levels from the finest (a walk of
  // one fetch per level cost llvmpipe 12 ms of `virtual`'s shading at 1280x720).
  void uploadTable() {
    const int n = pages_.pagesPerSide();
    glTextureSubImage2D(table_, 0, 0, 0, n, n, GL_RED_INTEGER, GL_UNSIGNED_INT, pages_.finestTable().data());
  }

  // Marks the pages the G-buffer's pixels need on the GPU, reads them back (at once by default:
  // the allocation serves this frame, and on llvmpipe the wait is the compute itself; with
  // virtual.async_marks the newest copy that has arrived), allocates tiles and uploads the page
  // table.
  // The edges criterion reads last frame's visibility (a texture of this frame's size); the
  // marking pass and the views ask through the same function (layouts/virtual_request.glsl).
  // The distance criterion reads the bend of the light's depth in the pages last frame drew
  // (depth_bend.h: brought up to date from the representation's depth atlas by the marking,
  // with the page table still holding last frame's allocation).
  void bindPreviousVisibility(const Program& p, TextureUnits& units, const PartContext& ctx) const {
    const bool previous = ctx.previousVisibility && ctx.previousVisibility->width() == ctx.width &&
                          ctx.previousVisibility->height() == ctx.height;
    units.bind(p, "u_previousVisibility", previous ? ctx.previousVisibility->id() : 0);
    p.set("u_hasPreviousVisibility", previous ? 1 : 0);
    units.bind(p, "u_virtualDepthBend", bendTexture_);
    p.set("u_virtualHasDepthBend", bendTexture_ ? 1 : 0);
  }

  // Only the distance criterion with a step reads the bend; otherwise the drawn tiles stay marked
  // stale until it does.
  void updateDepthBend(const PartContext& ctx) {
    bendTexture_ = 0;
    if (ctx.params->choice("virtual.criterion") != "distance" || !(ctx.params->f("virtual.depth_step") > 0.0f)) return;
    const Texture2D* depth = ctx.shadowDepth ? ctx.shadowDepth() : nullptr;
    bendTexture_ = bend_.update(*ctx.shaders, depth, sizes_.page, sizes_.poolSide, defines());
  }

  void markAndAllocate(const PartContext& ctx) {
    ProgramSpec spec{"virtual marks", {{GL_COMPUTE_SHADER, "passes/virtual_mark.comp"}}, defines()};
    draw_.clear();  // a marking program that does not build draws nothing (its error is shown)
    updateDepthBend(ctx);
    Program& p = ctx.shaders->get(spec);
    if (!p.valid()) return;
    fitted_ = ctx.params->choice("virtual.criterion") == "fitted";
    const GLuint out = fitted_ ? grid_ : marks_;
    const uint32_t zero = 0;
    glClearNamedBufferData(out, GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, &zero);
    p.use();
    TextureUnits units;
    ctx.bindTechnique(p, units);
    ctx.bindGBuffer(p, units);
    bindPreviousVisibility(p, units, ctx);
    bindStorage("PageMarks", marks_);
    bindStorage("FitGrid", grid_);
    glDispatchCompute((ctx.width + 15) / 16, (ctx.height + 15) / 16, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<uint32_t> values = readMarks(out, ctx.params->b("virtual.async_marks"));
    if (fitted_) {  // the CPU half of fitted virtual shadow maps; timed for the status line
      const auto start = std::chrono::steady_clock::now();
      fit_ = fitQuadtree(pages_, values);
      fitMs_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
      values = std::move(fit_.marks);
    }
    frame_ = pages_.update(values);
    draw_ = frame_.draw;
    uploadTable();
  }

  // This frame's marks (waiting for the marking pass), or with `async` the newest marks the GPU
  // has finished copying, a frame or more old: no stall, and pages newly in view are served by a
  // coarser resident page until their marks arrive (zeros before the first: the coarsest page).
  std::vector<uint32_t> readMarks(GLuint out, bool async) {
    std::vector<uint32_t> values(fitted_ ? fitGridValues() : static_cast<size_t>(pages_.flatSize()));
    const size_t bytes = values.size() * sizeof(uint32_t);
    if (!async) {
      markCopies_.reset();
      glGetNamedBufferSubData(out, 0, static_cast<GLsizeiptr>(bytes), values.data());
      return values;
    }
    if (!markCopies_ || markCopies_->latest().size() != bytes || markCopiesFitted_ != fitted_) {
      markCopies_ = std::make_unique<ReadbackRing>(bytes);  // another criterion or size: old marks mean nothing
      markCopiesFitted_ = fitted_;
    }
    markCopies_->copyFrom(out);
    markCopies_->poll();
    std::memcpy(values.data(), markCopies_->latest().data(), bytes);
    return values;
  }

  void addViewPass(FrameGraph& graph, const PartContext& ctx, int view, const std::string& pagesRes) {
    auto it = ctx.viewTargets.find(kViewNames[view]);
    if (it == ctx.viewTargets.end() || !it->second) return;
    Texture2D* target = it->second;
    const std::string res = std::string("view.") + kViewNames[view] + ctx.viewportTag;
    graph.add({res, {"gbuffer", pagesRes}, {res}, [this, ctx, target, view] {
                 drawPartView(ctx, target, "views/virtual.frag",
                              {.defines = "#define SL_VIRTUAL_VIEW " + std::to_string(view) + "\n",
                               .withGBuffer = true,
                               .bind = [this, &ctx](const Program& p, TextureUnits& units) {
                                 bindPreviousVisibility(p, units, ctx);
                               }});
               }});
    graph.requestSink(res);
  }

  // Drops the pages under each moving instance's bounds at the time the pages were drawn and
  // now, in the virtual map's uv; every page when a corner cannot be projected.
  int invalidateMoved(const Scene& scene, const glm::mat4& viewProj, double then, double now) {
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (size_t i = 0; i < scene.instances.size(); ++i) {
      if (scene.instances[i].motion.type == Motion::Type::None) continue;
      for (double t : {then, now}) {
        const Bounds b = scene.instanceBoundsAt(i, t);
        if (b.empty()) continue;
        for (const glm::vec3& corner : boxCorners(b)) {
          const glm::vec4 clip = viewProj * glm::vec4(corner, 1.0f);
          if (!(clip.w > 1e-6f)) {
            const int resident = frame_.resident;
            pages_.invalidate();
            return resident;
          }
          const glm::vec2 uv = glm::vec2(clip) / clip.w * 0.5f + 0.5f;
          lo = glm::min(lo, uv);
          hi = glm::max(hi, uv);
        }
      }
    }
    return pages_.invalidateRegion(lo.x, lo.y, hi.x, hi.y);
  }

  size_t fitGridValues() const {
    const size_t g = static_cast<size_t>(fitGridSide(pages_.pagesPerSide()));
    return 2u * g * g;
  }
  // SL_VIRTUAL_CRITERION_<CHOICE> <index> for each declared choice of virtual.criterion, and the
  // chosen one's flag SL_VIRTUAL_CRITERION_IS_<CHOICE>: a constant, not a uniform, since llvmpipe
  // runs every side of a uniform branch (the page marking took 41 ms at 1280x720 against 20 ms).
  std::string criterionDefines() const {
    std::string out;
    for (const ParamDecl& d : layout_.params())
      if (d.key == "virtual.criterion")
        for (size_t i = 0; i < d.choices.size(); ++i) {
          out += "#define " + choiceDefineName(d.key, d.choices[i]) + " " + std::to_string(i) + "\n";
          if (static_cast<int>(i) != criterion_) continue;
          // The chosen one's flag, as enumDefines names it (the technique prelude has it too).
          const std::string flag = choiceDefineName(d.key, "is." + d.choices[i]);
          out += "#ifndef " + flag + "\n#define " + flag + "\n#endif\n";
        }
    return out;
  }

  VirtualSizes sizes_;
  PageAllocator pages_;
  PageAllocator::Frame frame_;
  QuadtreeFit fit_;    // the last fitted criterion's quadtree (its marks moved out)
  int criterion_ = 0;  // virtual.criterion's index, this frame
  bool fitted_ = false;
  double fitMs_ = 0.0;
  int droppedByMotion_ = 0;  // pages dropped this frame because objects over them moved
  std::vector<int> draw_;    // flat page indices the shadow pass draws this frame
  VirtualDepthBend bend_;
  GLuint bendTexture_ = 0;  // what the marking and the views read this frame (0: none)
  GLuint marks_ = 0, grid_ = 0, table_ = 0;
  std::unique_ptr<ReadbackRing> markCopies_;  // virtual.async_marks: the marks of earlier frames
  bool markCopiesFitted_ = false;             // which buffer the copies are of
  int tableSide_ = 0;
  glm::mat4 drawnViewProj_{0.0f};
  const Scene* drawnScene_ = nullptr;
  int drawnCull_ = -1;
  double drawnTime_ = -1.0;
};

class VirtualLayout : public Layout {
 public:
  std::string id() const override { return "virtual"; }
  std::string help() const override {
    return "paged virtual shadow map (resolution-matched, Lefohn et al. 2007): one huge map over the scene, only "
           "the pages and mip levels the visible pixels need are rendered into a fixed atlas, and kept while "
           "nothing moves";
  }
  std::string glslModule() const override { return "layouts/virtual.glsl"; }
  std::vector<ParamDecl> params() const override {
    return {
        {.key = "virtual.size",
         .type = ParamType::Int,
         .min = 1024,
         .max = 131072,
         .defaultValue = 16384,
         .unit = "texels",
         .help = "virtual map texels per side (rounded down to the page size times a power of two)",
         .logScale = true},
        {.key = "virtual.page",
         .type = ParamType::Int,
         .min = 32,
         .max = 512,
         .defaultValue = 128,
         .unit = "texels",
         .help = "texels per page side: the unit of allocation and of drawing",
         .logScale = true},
        {.key = "virtual.pool",
         .type = ParamType::Int,
         .min = 64,
         .max = 8192,
         .defaultValue = 1920,
         .unit = "texels",
         .help =
             "physical atlas texels per side (whole pages; 1920 = 15 x 15 pages of 128², with the page table under a "
             "quarter of a 4096² map): when the pages asked for do not fit, the finest "
             "level's pages are replaced by coarser ones and the status says so",
         .logScale = true},
        {.key = "virtual.lod_bias",
         .type = ParamType::Float,
         .min = -3,
         .max = 3,
         .defaultValue = 0,
         .unit = "levels",
         .help = "shift of the mip level each pixel asks for (negative: finer pages than its footprint)"},
        {.key = "virtual.criterion",
         .type = ParamType::Enum,
         .defaultValue = 0,
         .help = "which page and level each visible pixel asks for (the survey: the adaptive methods \"mainly differ "
                 "in termination criteria\"): footprint (resolution-matched, Lefohn et al. 2007), distance (tiled "
                 "maps' heuristic after Arvo 2004: the pixel's world size, near the light depth's discontinuities), "
                 "edges (adaptive shadow maps, "
                 "Fernando et al. 2001: full resolution near last frame's shadow edges, coarser elsewhere), fitted "
                 "(fitted virtual shadow maps, Giegl & Wimmer 2007: the footprints gathered into a grid, read back "
                 "and fitted into a quadtree on the CPU)",
         .choices = {"footprint", "distance", "edges", "fitted"}},
        {.key = "virtual.edge_coarsen",
         .type = ParamType::Int,
         .min = 1,
         .max = 6,
         .defaultValue = 3,
         .unit = "levels",
         .help = "criteria edges and distance: how many levels coarser a pixel away from shadow edges (edges) or "
                 "from the light depth's discontinuities (distance) asks for"},
        {.key = "virtual.depth_step",
         .type = ParamType::Float,
         .min = 0,
         .max = 0.05,
         .defaultValue = 0.0005,
         .unit = "depth [0,1]",
         .help = "criterion distance (tiled maps, Arvo 2004): the second difference of the light's depth (3x3 texels "
                 "of last frame's page) above which a point counts as near a depth discontinuity and keeps its "
                 "distance level; 0: every point keeps it (the distance heuristic alone)"},
        {.key = "virtual.cache",
         .type = ParamType::Bool,
         .defaultValue = 1,
         .help = "keep drawn pages between frames while the light, the scene and the map settings stay the same"},
        {.key = "virtual.async_marks",
         .type = ParamType::Bool,
         .defaultValue = 1,
         .help = "allocate pages from the newest page marks the GPU has finished (a frame or more old on a GPU) "
                 "instead of waiting for this frame's: no CPU stall in the frame; pages newly in view are served "
                 "by a coarser resident page until their marks arrive (beyond Lefohn et al., who read back in "
                 "the frame)"}};
  }
  // The whole scene in one light view: it does not follow the camera or moving objects, so pages
  // stay valid.
  LightSpace compute(const LayoutInput& in) const override {
    // Over the scene's whole motion, so that the view (and the pages of static parts) stay put;
    // a point light as a spot aimed at all of it.
    const auto corners = boxCorners(in.scene->motionEnvelope());
    const Light light =
        in.shadowedLight().type == Light::Type::Point ? pointAsSpot(in.shadowedLight(), corners) : in.shadowedLight();
    const glm::mat4 view = lightViewMatrix(light, in.jitter.rotationRad);
    const int size = virtualSizes(*in.params).virtualSize;
    const bool snap = in.params->b("layout.snap");
    if (light.type == Light::Type::Spot)
      return LightSpace::single(fitPerspective(light, view, corners, corners, size, false, snap, in.jitter), size);
    return LightSpace::single(fitOrthographic(view, corners, corners, size, snap, in.jitter), size);
  }
  std::unique_ptr<LayoutState> createState() const override { return std::make_unique<VirtualState>(*this); }
};

}  // namespace

void registerAdaptiveLayouts(std::vector<std::unique_ptr<Layout>>& out) {
  out.push_back(std::make_unique<VirtualLayout>());
}

}  // namespace sl
