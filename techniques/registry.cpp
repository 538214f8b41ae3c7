// The one list of technique families (each folder's family.cpp declares its parts and presets),
// the parameters every technique has, and techniques built from presets.
#include "technique.h"
#include "param_hints.h"
#include "part/common_view_keys.h"

namespace sl {

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

// A scene of several lights: how many are shadowed and the texels their maps share.
std::vector<ParamDecl> severalLightsParams() {
  return {
      {.key = "lights.shadowed",
       .type = ParamType::Int,
       .min = 1,
       .max = kMaxSceneLights,
       .defaultValue = kMaxSceneLights,
       .unit = "lights",
       .help = "a scene of several lights: the first this many shadow-casting lights of its list get maps of their "
               "own, later ones light through casters (a shadow budget; the bench sweeps it for the cost per light)"},
      {.key = "lights.texel_budget",
       .type = ParamType::Float,
       .min = 0,
       .max = 1024,
       .defaultValue = 24,
       .unit = "M texels",
       .help = "a scene of several shadowed lights: the texels all their maps share (24 M: four cube lamps at "
               "1024² a face), given by the screen each light's range covers, each map shadowmap.size halved 0 or "
               "more times (at least 64); 0 = every light at shadowmap.size"},
      {.key = "lights.one_atlas",
       .type = ParamType::Bool,
       .defaultValue = 0,
       .help = "with a texel budget: every light's map a region of one depth layer shared by all the lights, "
               "packed by the sizes the budget gave (one texture for all; a light of several layers, a paged or "
               "pre-filtered map keeps maps of its own)"},
  };
}

}  // namespace

const std::vector<ParamDecl>& commonParams() {
  static const std::vector<ParamDecl> decls = [] {
    std::vector<ParamDecl> d = {
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
    const std::vector<ParamDecl> lights = severalLightsParams();
    d.insert(d.end(), lights.begin(), lights.end());
    return d;
  }();
  return decls;
}

// The families, in the order `shadowlab list` shows their parts and presets. A new family adds
// its folder with a family.cpp and one line here.
Family depthFamily();
Family accumulationFamily();
Family layoutsFamily();
Family adaptiveFamily();
Family prefilteredFamily();
Family irregularFamily();
Family reconstructionFamily();
Family softFamily();
Family deepFamily();
Family optimizedPcfFamily();
Family pointFamily();

const ColourKey* viewColourKey(const std::string& viewName) {
  if (const ColourKey* key = commonViewColourKey(viewName)) return key;
  for (const Family& f : allFamilies()) {
    auto it = f.viewKeys.find(viewName);
    if (it != f.viewKeys.end()) return &it->second;
  }
  return nullptr;
}

std::vector<std::string> viewsWithColourKeys() {
  std::vector<std::string> names = commonViewsWithColourKeys();
  for (const Family& f : allFamilies())
    for (const auto& [name, key] : f.viewKeys) names.push_back(name);
  return names;
}

const std::vector<Family>& allFamilies() {
  static const std::vector<Family> list = [] {
    std::vector<Family> v;
    for (Family (*make)() :
         {depthFamily, accumulationFamily, layoutsFamily, adaptiveFamily, prefilteredFamily, irregularFamily,
          reconstructionFamily, softFamily, deepFamily, optimizedPcfFamily, pointFamily})
      v.push_back(make());
    return v;
  }();
  return list;
}

namespace {

// Every family's parts of one kind, in family order.
template <typename T>
std::vector<const T*> gather(std::vector<std::unique_ptr<T>> Family::*parts) {
  std::vector<const T*> out;
  for (const Family& f : allFamilies())
    for (const auto& p : f.*parts) out.push_back(p.get());
  return out;
}

}  // namespace

const std::vector<const Layout*>& allLayouts() {
  static const auto list = gather(&Family::layouts);
  return list;
}

const std::vector<const Representation*>& allRepresentations() {
  static const auto list = gather(&Family::representations);
  return list;
}

const std::vector<const Accumulation*>& allAccumulations() {
  static const auto list = gather(&Family::accumulations);
  return list;
}

const std::vector<Preset>& allPresets() {
  static const std::vector<Preset> presets = [] {
    std::vector<Preset> v;
    for (const Family& f : allFamilies()) v.insert(v.end(), f.presets.begin(), f.presets.end());
    return v;
  }();
  return presets;
}

template <typename T>
static const T* findById(const std::vector<const T*>& list, const std::string& id) {
  for (const T* p : list)
    if (p->id() == id) return p;
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
