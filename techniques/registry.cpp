// The one list of technique families. A new paper adds its register call here and nothing else.
#include "technique.h"
#include "param_hints.h"

#include "adaptive/virtual_layout.h"
#include "deep/deep_representation.h"
#include "depth/depth_representations.h"
#include "irregular/irregular.h"
#include "layouts/cascaded.h"
#include "layouts/face_partitioned.h"
#include "layouts/layouts.h"
#include "layouts/lispsm.h"
#include "layouts/logpsm.h"
#include "prefiltered/prefiltered_representations.h"
#include "layouts/psm.h"
#include "layouts/tsm.h"
#include "reconstruction/reconstruction.h"
#include "soft/pcss.h"

namespace sl {

void registerAccumulations(std::vector<std::unique_ptr<Accumulation>>& out);

namespace {

std::vector<std::string> layoutIds() {
  std::vector<std::string> ids;
  for (const auto& l : allLayouts()) ids.push_back(l->id());
  return ids;
}

// The composition's layout as a parameter: any preset's representation and accumulation over any
// layout (pixel-correct over TSM, VSM over cascades), chosen like any other value, swept by
// bench. Changing it rebuilds the technique (recomposed), since the parameters change with it.
ParamDecl layoutChoice() {
  return {.key = kLayoutParam,
          .type = ParamType::Enum,
          .defaultValue = 0,  // set to the preset's own layout by makeTechnique
          .help =
              "where the texels go: any layout under this preset's representation and accumulation (the "
              "preset's own by default; its layout parameters come with it)",
          .choices = layoutIds()};
}

}  // namespace

const std::vector<ParamDecl>& commonParams() {
  static const std::vector<ParamDecl> decls = {
      layoutChoice(),
      {.key = "shadowmap.size",
       .type = ParamType::Int,
       .min = 64,
       .max = 8192,
       .defaultValue = 2048,
       .unit = "texels",
       .help = "shadow-map texels per side",
       .logScale = true},
      {.key = "shadowmap.cull",
       .type = ParamType::Enum,
       .defaultValue = 0,
       .help = "faces stored in the shadow map: front (standard), back (second-depth shadow mapping, Wang & Molnar "
               "1994), or both",
       .choices = {"front", "back", "both"}},
      {.key = "shadowmap.cull_instances",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "skip, per light view (each cascade, face or layer), instances whose bounds lie outside its window: "
               "they cannot cast into it (same image, less drawing)"},
      {.key = "bias.mode",
       .type = ParamType::Enum,
       .defaultValue = 2,
       .help = "depth bias against self-shadowing (acne): none, constant, slope-scaled (+constant), normal offset "
               "(+constant), receiver plane (+constant: each filter tap compares against the receiver's plane "
               "extrapolated to that texel; Isidoro 2006)",
       .choices = {"none", "constant", "slope", "normal-offset", "receiver-plane"}},
      {.key = "bias.constant",
       .type = ParamType::Float,
       .min = 0,
       .max = 0.05,
       .defaultValue = 0.0005,
       .unit = "depth [0,1]",
       .help = "constant depth offset",
       .logScale = true},
      {.key = "bias.slope",
       .type = ParamType::Float,
       .min = 0,
       .max = 8,
       .defaultValue = 1.0,
       .unit = "texels",
       .help = "slope-scaled bias: depth change across this many texels of a tilted receiver"},
      {.key = "bias.normal",
       .type = ParamType::Float,
       .min = 0,
       .max = 8,
       .defaultValue = 1.0,
       .unit = "texels",
       .help =
           "normal offset: receiver moved along its normal by this many texel sizes (times sin of the light angle)"},
      {.key = "layout.snap",
       .type = ParamType::Bool,
       .defaultValue = 1,
       .help = "move the light frustum by whole texels and keep the texel size on a fixed ladder (less flicker)"},
  };
  return decls;
}

const std::vector<std::unique_ptr<Layout>>& allLayouts() {
  static const auto list = [] {
    std::vector<std::unique_ptr<Layout>> v;
    registerBasicLayouts(v);
    registerWarpedLayouts(v);
    registerLogLayouts(v);
    registerCascadedLayouts(v);
    registerTrapezoidalLayouts(v);
    registerPerspectiveLayouts(v);
    registerFacePartitionedLayouts(v);
    registerAdaptiveLayouts(v);
    return v;
  }();
  return list;
}

const std::vector<std::unique_ptr<Representation>>& allRepresentations() {
  static const auto list = [] {
    std::vector<std::unique_ptr<Representation>> v;
    registerDepthRepresentations(v);
    registerPrefilteredRepresentations(v);
    registerIrregularRepresentations(v);
    registerReconstructionRepresentations(v);
    registerSoftRepresentations(v);
    registerDeepRepresentations(v);
    return v;
  }();
  return list;
}

const std::vector<std::unique_ptr<Accumulation>>& allAccumulations() {
  static const auto list = [] {
    std::vector<std::unique_ptr<Accumulation>> v;
    registerAccumulations(v);
    registerForwardAccumulation(v);
    return v;
  }();
  return list;
}

namespace {

// The depth test over the focused (or whole-scene) map, with its filters.
void addDepthTestPresets(std::vector<Preset>& v) {
  v.insert(
      v.end(),
      {
          {"standard", "focused shadow map, nearest depth test", "focused", "depth-nearest", "none", {}},
          {"uniform",
           "one shadow map over the whole scene, nearest depth test",
           "uniform",
           "depth-nearest",
           "none",
           {}},
          {"pcf", "focused shadow map, 3x3 box PCF", "focused", "depth-pcf", "none", {"pcf.kernel=3"}},
          {"poisson", "focused shadow map, rotated Poisson-disk PCF", "focused", "depth-poisson", "none", {}},
          {"bilinear", "focused shadow map, hardware bilinear depth compare", "focused", "depth-bilinear", "none", {}},
      });
}

// The pixel-correct paper's presets (Scherzer et al. 2007) and the LiSPSM layout it pairs with.
void addPixelCorrectPresets(std::vector<Preset>& v) {
  v.insert(v.end(),
           {
               {"pixel-correct",
                "focused map, nearest test, confidence-weighted screen-space history (Scherzer et al. 2007)",
                "focused",
                "depth-nearest",
                "pixel-correct",
                {}},
               {"lispsm",
                "light space perspective shadow map (Wimmer et al. 2004), nearest depth test",
                "lispsm",
                "depth-nearest",
                "none",
                {}},
               {"pixel-correct-lispsm",
                "pixel-correct over a LiSPSM layout, as the paper pairs them",
                "lispsm",
                "depth-nearest",
                "pixel-correct",
                {}},
               {"pixel-correct-at-rest",
                "pixel-correct that shows the layout's plain test while the camera moves and keeps the most confident "
                "test at rest",
                "focused",
                "depth-nearest",
                "pixel-correct",
                {"pc.while_moving=test", "pc.keep_best=on"}},
               {"pixel-correct-pcf",
                "pixel-correct with 3x3 PCF tests as f(n): smoother edges while converging",
                "focused",
                "depth-pcf",
                "pixel-correct",
                {"pcf.kernel=3"}},
           });
}

// Warping and partitioning layouts with the nearest test, and pixel-correct over cascades.
void addWarpingPresets(std::vector<Preset>& v) {
  v.insert(
      v.end(),
      {
          {"psm",
           "perspective shadow map (Stamminger & Drettakis 2002): post-perspective space, virtual camera slid back, "
           "nearest depth test",
           "psm",
           "depth-nearest",
           "none",
           {}},
          {"logpsm",
           "logarithmic warp along the view (after Lloyd et al. 2008), casters tessellated within an error budget, "
           "nearest depth test",
           "logpsm",
           "depth-nearest",
           "none",
           {}},
          {"tsm",
           "trapezoidal shadow map (Martin & Tan 2004): trapezoid around the view frustum to the square map, 80 % "
           "rule, "
           "nearest depth test",
           "tsm",
           "depth-nearest",
           "none",
           {}},
          {"cascaded",
           "cascaded / parallel-split shadow maps (Zhang et al. 2006, Engel 2007): 4 snapped splits of shadowmap.size² "
           "each, practical split scheme, blended borders, nearest depth test",
           "cascaded",
           "depth-nearest",
           "none",
           {}},
          {"pixel-correct-cascaded",
           "pixel-correct over cascades: jitter and confidence in each split's own texels",
           "cascaded",
           "depth-nearest",
           "pixel-correct",
           {}},
          {"face-partitioned",
           "face partitioning (Lloyd et al. 2006): one LiSPSM map per side face of the view frustum, nearest depth "
           "test",
           "face-partitioned",
           "depth-nearest",
           "none",
           // Measured: its warped maps' texels are anisotropic, and the slope bias measures the smaller
           // side; one texel of slope leaves acne near the horizon (techniques/layouts/README.md).
           {"bias.slope=2"}},
          {"sdsm",
           "sample-distribution shadow maps (Lauritzen et al. 2011): cascades split over the visible depth range from "
           "a GPU reduction (one frame of latency), nearest depth test",
           "cascaded",
           "depth-nearest",
           "none",
           {"fit.sdsm=on"}},
      });
}

// The virtual map's pages under each page criterion.
void addVirtualPresets(std::vector<Preset>& v) {
  v.insert(
      v.end(),
      {
          {"virtual",
           "paged virtual shadow map (Lefohn et al. 2007): 16384² virtual texels over the scene, only the pages and "
           "mip "
           "levels the visible pixels need, in one 1920² atlas, cached while nothing moves; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {}},
          {"tiled",
           "the virtual map's pages chosen by a distance heuristic (after Arvo 2004, tiled shadow maps): each pixel's "
           "world size decides its level, the atlas is the texel budget; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {"virtual.criterion=distance"}},
          {"adaptive",
           "adaptive shadow maps over the virtual map's pages (Fernando et al. 2001, Lefohn et al. 2006): full "
           "resolution only near last frame's shadow edges, 3 levels coarser elsewhere; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {"virtual.criterion=edges"}},
          {"fitted-virtual",
           "fitted virtual shadow maps (Giegl & Wimmer 2007) over the virtual map's pages: the pixels' footprints "
           "gathered into a grid over the light's view, read back and fitted into a quadtree on the CPU, whose leaves "
           "are the pages drawn; nearest depth test",
           "virtual",
           "depth-nearest",
           "none",
           {"virtual.criterion=fitted"}},
      });
}

}  // namespace

const std::vector<Preset>& allPresets() {
  static const std::vector<Preset> presets = [] {
    std::vector<Preset> v;
    addDepthTestPresets(v);
    addPixelCorrectPresets(v);
    addWarpingPresets(v);
    addVirtualPresets(v);
    addPrefilteredPresets(v);
    addIrregularPresets(v);
    addReconstructionPresets(v);
    addSoftPresets(v);
    addDeepPresets(v);
    return v;
  }();
  return presets;
}

template <typename T>
static const T* findById(const std::vector<std::unique_ptr<T>>& list, const std::string& id) {
  for (const auto& p : list)
    if (p->id() == id) return p.get();
  return nullptr;
}

const Layout* findLayout(const std::string& id) { return findById(allLayouts(), id); }
const Representation* findRepresentation(const std::string& id) { return findById(allRepresentations(), id); }
const Accumulation* findAccumulation(const std::string& id) { return findById(allAccumulations(), id); }
const Preset* findPreset(const std::string& id) {
  for (const auto& p : allPresets())
    if (p.id == id) return &p;
  return nullptr;
}

Technique makeTechnique(const std::string& presetId, const std::vector<std::string>& overrides) {
  const Preset* preset = findPreset(presetId);
  if (!preset) {
    std::string ids;
    for (const auto& p : allPresets()) ids += (ids.empty() ? "" : ", ") + p.id;
    throw ParamError("unknown technique '" + presetId + "' (available: " + ids + ")");
  }
  // The layout comes first: the other overrides may set its parameters.
  std::string layoutId = preset->layout;
  for (const auto& o : overrides)
    if (o.rfind(std::string(kLayoutParam) + "=", 0) == 0) layoutId = o.substr(std::string(kLayoutParam).size() + 1);
  Technique t;
  t.presetId = presetId;
  t.layout = findLayout(layoutId);
  if (!t.layout) {
    std::string ids;
    for (const auto& id : layoutIds()) ids += (ids.empty() ? "" : ", ") + id;
    throw ParamError(std::string(kLayoutParam) + ": no layout '" + layoutId + "' (layouts: " + ids + ")");
  }
  t.representation = findRepresentation(preset->representation);
  t.accumulation = findAccumulation(preset->accumulation);
  if (!t.layout || !t.representation || !t.accumulation)
    throw ParamError("preset '" + presetId + "' names a part that is not registered");
  std::vector<ParamDecl> decls = commonParams();
  for (auto&& part : {t.layout->params(), t.representation->params(), t.accumulation->params()})
    decls.insert(decls.end(), part.begin(), part.end());
  t.params = ParamSet(std::move(decls));
  t.params.setFromString(kLayoutParam, layoutId);
  // A preset's overrides of its own layout's parameters do not apply over another layout.
  for (const auto& o : preset->overrides)
    if (t.params.has(o.substr(0, o.find('='))) || layoutId == preset->layout) t.params.setAssignment(o);
  for (const auto& o : overrides) {
    const std::string key = o.substr(0, o.find('='));
    if (o.find('=') != std::string::npos && !key.empty() && !t.params.has(key))
      throw ParamError(unknownParameterMessage(presetId, t.params, key));
    t.params.setAssignment(o);
  }
  return t;
}

Technique recomposed(const Technique& t) {
  if (!t.layout || !t.params.has(kLayoutParam) || t.params.choice(kLayoutParam) == t.layout->id()) return t;
  Technique fresh = makeTechnique(t.presetId, {std::string(kLayoutParam) + "=" + t.params.choice(kLayoutParam)});
  for (const ParamDecl& d : t.params.decls())
    if (d.key != kLayoutParam && fresh.params.has(d.key)) fresh.params.set(d.key, t.params.get(d.key));
  return fresh;
}

}  // namespace sl
