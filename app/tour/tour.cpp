// parseTour / loadTour: the tour format of docs/tour-format.md, validated as strictly as scenes
// (scene/json_reader.h does the value checks), so a typo in a slide fails when the tour loads,
// not in front of an audience.
#include "tour/tour.h"

#include "render/renderer.h"
#include "scene/json_reader.h"
#include "technique.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sl {
namespace {

using nlohmann::json;

std::string joined(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

std::vector<std::string> stringList(const JsonReader& r, const json& j, const std::string& where) {
  if (!j.is_array()) r.expected(where, "an array of strings", j);
  std::vector<std::string> out;
  for (size_t i = 0; i < j.size(); ++i) out.push_back(r.string(j[i], where + "[" + std::to_string(i) + "]"));
  return out;
}

TourCamera parseCamera(const JsonReader& r, const json& j, const std::string& where) {
  TourCamera c;
  if (j.is_string()) {
    c.name = r.string(j, where);
    return c;
  }
  r.checkKeys(j, where, {"name", "position", "target", "path", "time"});
  if (const json* n = JsonReader::find(j, "name")) c.name = r.string(*n, where + ".name");
  const json* p = JsonReader::find(j, "position");
  const json* t = JsonReader::find(j, "target");
  const json* path = JsonReader::find(j, "path");
  if ((p || t) && (path || JsonReader::find(j, "name")))
    r.fail(where, "give either 'position' and 'target', or 'path', or 'name'");
  if (p || t) {
    if (!p || !t) r.fail(where, "a camera pose needs both 'position' and 'target'");
    c.kind = TourCamera::Kind::Pose;
    c.position = r.vec3(*p, where + ".position");
    c.target = r.vec3(*t, where + ".target");
    if (!(glm::length(c.target - c.position) > 1e-6f)) r.fail(where, "camera position equals target");
  } else if (path) {
    c.kind = TourCamera::Kind::Path;
    c.name = r.string(*path, where + ".path");
    if (const json* time = JsonReader::find(j, "time")) {
      c.pathTime = float(r.number(*time, where + ".time"));
      if (c.pathTime < 0.0f) r.fail(where + ".time", "must be >= 0 seconds");
    }
  } else if (JsonReader::find(j, "time")) {
    r.fail(where + ".time", "'time' belongs to a camera 'path'");
  }
  return c;
}

// The debug views a technique offers, from its part states (no GL needed to ask), and "error"
// (kErrorView: the difference to the ray-traced reference, which every viewport can show).
std::vector<std::string> offeredViews(const Technique& t) {
  std::vector<std::string> views = Viewport(t).availableViews();
  views.push_back(kErrorView);
  return views;
}

TourViewport parseViewport(const JsonReader& r, const json& j, const std::string& where,
                           const std::vector<std::string>& planned, std::vector<std::string>& missing) {
  TourViewport v;
  if (j.is_string()) {
    v.technique = r.string(j, where);
  } else {
    r.checkKeys(j, where, {"technique", "set", "views", "label", "enlarge"});
    const json* t = JsonReader::find(j, "technique");
    if (!t) r.fail(where, "missing 'technique' (a preset id; `shadowlab list` shows them)");
    v.technique = r.string(*t, where + ".technique");
    if (const json* s = JsonReader::find(j, "set")) v.overrides = stringList(r, *s, where + ".set");
    if (const json* s = JsonReader::find(j, "views")) v.views = stringList(r, *s, where + ".views");
    if (const json* s = JsonReader::find(j, "label")) v.label = r.string(*s, where + ".label");
    if (const json* s = JsonReader::find(j, "enlarge")) {
      v.enlarged = r.string(*s, where + ".enlarge");
      if (std::find(v.views.begin(), v.views.end(), v.enlarged) == v.views.end())
        r.fail(where + ".enlarge",
               "'" + v.enlarged + "' is not one of this viewport's views (" + joined(v.views) + ")");
    }
  }
  if (!findPreset(v.technique)) {
    if (std::find(planned.begin(), planned.end(), v.technique) != planned.end()) {
      // Planned: its parameters and views cannot be checked until it exists.
      if (std::find(missing.begin(), missing.end(), v.technique) == missing.end()) missing.push_back(v.technique);
      return v;
    }
    std::vector<std::string> ids;
    for (const auto& p : allPresets()) ids.push_back(p.id);
    r.fail(where + ".technique", "unknown technique '" + v.technique + "' (available: " + joined(ids) +
                                     "; list a planned one under the step's \"requires\")");
  }
  Technique technique;
  try {
    technique = makeTechnique(v.technique, v.overrides);
  } catch (const ParamError& e) {
    r.fail(where + ".set", e.what());
  }
  const std::vector<std::string> offered = offeredViews(technique);
  for (size_t i = 0; i < v.views.size(); ++i)
    if (std::find(offered.begin(), offered.end(), v.views[i]) == offered.end())
      r.fail(where + ".views[" + std::to_string(i) + "]",
             "technique '" + v.technique + "' has no view '" + v.views[i] + "' (views: " + joined(offered) + ")");
  return v;
}

std::vector<int> parseFrames(const JsonReader& r, const json& j, const std::string& where) {
  if (!j.is_array() || j.empty() || j.size() > 8) r.expected(where, "an array of 1 to 8 frame counts", j);
  std::vector<int> frames;
  for (size_t i = 0; i < j.size(); ++i) {
    const std::string w = where + "[" + std::to_string(i) + "]";
    frames.push_back(r.integer(j[i], w, 1, 1000));
    if (i > 0 && frames[i] <= frames[i - 1]) r.fail(w, "frame counts must increase");
  }
  return frames;
}

TourPlot parsePlot(const JsonReader& r, const json& j, const std::string& where) {
  r.checkKeys(j, where, {"kind", "techniques", "pixel", "point"});
  TourPlot p;
  const json* k = JsonReader::find(j, "kind");
  if (!k) r.fail(where, "missing 'kind' (dpds or visibility)");
  const std::string kind = r.string(*k, where + ".kind");
  if (kind == "dpds")
    p.kind = TourPlot::Kind::Dpds;
  else if (kind == "visibility")
    p.kind = TourPlot::Kind::Visibility;
  else
    r.fail(where + ".kind", "unknown plot kind '" + kind + "' (dpds, visibility)");
  if (const json* t = JsonReader::find(j, "techniques")) p.techniques = stringList(r, *t, where + ".techniques");
  for (size_t i = 0; i < p.techniques.size(); ++i) {
    const std::string& spec = p.techniques[i];
    const std::string id = spec.substr(0, spec.find(':'));
    if (!findPreset(id)) r.fail(where + ".techniques[" + std::to_string(i) + "]", "unknown technique '" + id + "'");
  }
  if (p.kind == TourPlot::Kind::Visibility && p.techniques.empty())
    r.fail(where + ".techniques", "a visibility plot needs pre-filtered techniques");
  if (const json* px = JsonReader::find(j, "pixel")) {
    if (p.kind != TourPlot::Kind::Visibility) r.fail(where + ".pixel", "only a visibility plot has a pixel");
    if (!px->is_array() || px->size() != 2) r.expected(where + ".pixel", "[x, y]", *px);
    p.pixel = {r.integer((*px)[0], where + ".pixel[0]", 0, 8192), r.integer((*px)[1], where + ".pixel[1]", 0, 8192)};
  }
  if (const json* pt = JsonReader::find(j, "point")) {
    if (p.kind != TourPlot::Kind::Visibility) r.fail(where + ".point", "only a visibility plot has a point");
    if (JsonReader::find(j, "pixel")) r.fail(where + ".point", "give either 'pixel' or 'point', not both");
    const std::vector<float> f = r.numbers(*pt, where + ".point", 2, false);
    for (float v : f)
      if (!(v >= 0.0f && v <= 1.0f)) r.fail(where + ".point", "shares of the panel's width and height, in [0, 1]");
    p.point = {f[0], f[1]};
  }
  return p;
}

// {"better": i, "than": j, "factor": f} or {"converges": i, "factor": f}; i, j: viewports from 1.
TourClaim parseClaim(const JsonReader& r, const json& j, const std::string& where, int viewports) {
  r.checkKeys(j, where, {"better", "than", "converges", "factor", "metric"});
  TourClaim c;
  const json* better = JsonReader::find(j, "better");
  const json* converges = JsonReader::find(j, "converges");
  if (!better == !converges) r.fail(where, "a claim is either {\"better\": i, \"than\": j} or {\"converges\": i}");
  if (better) {
    c.viewport = r.integer(*better, where + ".better", 1, viewports);
    const json* than = JsonReader::find(j, "than");
    if (!than) r.fail(where, "missing 'than' (the viewport it is better than)");
    c.than = r.integer(*than, where + ".than", 1, viewports);
    if (c.than == c.viewport) r.fail(where + ".than", "a viewport cannot be better than itself");
  } else {
    c.kind = TourClaim::Kind::Converges;
    c.viewport = r.integer(*converges, where + ".converges", 1, viewports);
    if (JsonReader::find(j, "than")) r.fail(where + ".than", "only a 'better' claim has 'than'");
  }
  if (const json* m = JsonReader::find(j, "metric")) {
    const std::string metric = r.string(*m, where + ".metric");
    if (metric == "false_light")
      c.metric = TourClaim::Metric::FalseLight;
    else if (metric == "false_shadow")
      c.metric = TourClaim::Metric::FalseShadow;
    else if (metric == "image_wrong")
      c.metric = TourClaim::Metric::ImageWrong;
    else if (metric != "wrong")
      r.fail(where + ".metric", "unknown metric '" + metric + "' (wrong, false_light, false_shadow, image_wrong)");
  }
  if (const json* f = JsonReader::find(j, "factor")) {
    c.factor = r.number(*f, where + ".factor");
    if (!(c.factor >= 1.0 && c.factor <= 1000.0)) r.fail(where + ".factor", "must be in [1, 1000]");
  }
  return c;
}

const std::vector<std::string> kStepKeys = {"title",     "caption", "scene", "camera", "light",
                                            "viewports", "frames",  "plot",  "claims", "requires"};

TourStep parseStep(const JsonReader& r, const json& j, const std::string& where) {
  r.checkKeys(j, where, kStepKeys);
  TourStep s;
  const json* title = JsonReader::find(j, "title");
  if (!title) r.fail(where, "missing 'title'");
  s.title = r.string(*title, where + ".title");
  if (const json* c = JsonReader::find(j, "caption")) s.caption = r.string(*c, where + ".caption");
  if (const json* sc = JsonReader::find(j, "scene")) s.scene = r.string(*sc, where + ".scene");
  if (s.scene.empty()) r.fail(where + ".scene", "must not be empty");
  if (const json* c = JsonReader::find(j, "camera")) s.camera = parseCamera(r, *c, where + ".camera");
  if (const json* l = JsonReader::find(j, "light")) {
    const std::vector<float> a = r.numbers(*l, where + ".light", 2, false);
    if (a[1] < -90.0f || a[1] > 90.0f) r.fail(where + ".light", "elevation must be in [-90, 90] degrees");
    s.setLight = true;
    s.lightAngles = {a[0], a[1]};
  }
  std::vector<std::string> planned;
  if (const json* q = JsonReader::find(j, "requires")) planned = stringList(r, *q, where + ".requires");
  const json* vps = JsonReader::find(j, "viewports");
  if (!vps) r.fail(where, "missing 'viewports' (1 to 4 techniques)");
  if (!vps->is_array() || vps->empty() || vps->size() > 4) r.expected(where + ".viewports", "1 to 4 viewports", *vps);
  for (size_t i = 0; i < vps->size(); ++i)
    s.viewports.push_back(
        parseViewport(r, (*vps)[i], where + ".viewports[" + std::to_string(i) + "]", planned, s.missing));
  if (const json* f = JsonReader::find(j, "frames")) s.frames = parseFrames(r, *f, where + ".frames");
  if (const json* p = JsonReader::find(j, "plot")) s.plot = parsePlot(r, *p, where + ".plot");
  if (const json* c = JsonReader::find(j, "claims")) {
    if (!c->is_array()) r.expected(where + ".claims", "an array of claims", *c);
    for (size_t i = 0; i < c->size(); ++i)
      s.claims.push_back(
          parseClaim(r, (*c)[i], where + ".claims[" + std::to_string(i) + "]", static_cast<int>(s.viewports.size())));
    for (const TourClaim& claim : s.claims)
      if (claim.kind == TourClaim::Kind::Converges && s.frames.size() < 2)
        r.fail(where + ".claims", "a 'converges' claim needs at least two frame counts in 'frames'");
  }
  return s;
}

std::string stepWhere(size_t i, const json& step) {
  std::string where = "steps[" + std::to_string(i) + "]";
  if (step.is_object() && step.contains("title") && step["title"].is_string())
    where += " (\"" + step["title"].get<std::string>() + "\")";
  return where;
}

}  // namespace

std::string TourStep::shownCaption() const {
  if (built()) return caption;
  return "Not built yet (" + joined(missing) + "): this step shows once the technique exists. " + caption;
}

Tour parseTour(const std::string& text, const std::string& fileName) {
  JsonReader r(fileName);
  try {
    json root;
    try {
      root = json::parse(text);
    } catch (const json::parse_error& e) {
      r.fail("", std::string("invalid JSON: ") + e.what());
    } catch (const json::exception& e) {
      // nlohmann reports literals like 1e999 this way (out_of_range 406), as scene files meet it.
      r.fail("", std::string("invalid JSON (numbers must be finite): ") + e.what());
    }
    r.checkKeys(root, "", {"title", "description", "steps"});
    Tour tour;
    tour.file = fileName;
    if (const json* t = JsonReader::find(root, "title")) tour.title = r.string(*t, "title");
    if (const json* d = JsonReader::find(root, "description")) r.string(*d, "description");
    const json* steps = JsonReader::find(root, "steps");
    if (!steps) r.fail("", "missing 'steps'");
    if (!steps->is_array() || steps->empty()) r.expected("steps", "a non-empty array of steps", *steps);
    for (size_t i = 0; i < steps->size(); ++i)
      tour.steps.push_back(parseStep(r, (*steps)[i], stepWhere(i, (*steps)[i])));
    return tour;
  } catch (const SceneError& e) {
    throw TourError(e.what());
  }
}

Tour loadTour(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw TourError(path + ": cannot open tour file");
  std::ostringstream ss;
  ss << in.rdbuf();
  if (in.bad()) throw TourError(path + ": cannot read tour file");
  return parseTour(ss.str(), path);
}

std::string describeStep(const Tour& tour, size_t step) {
  return "steps[" + std::to_string(step) + "] (\"" + tour.steps.at(step).title + "\")";
}

std::string stepScenePath(const Tour& tour, size_t step) {
  namespace fs = std::filesystem;
  std::string scene = tour.steps.at(step).scene;
  // A path (it has a folder or an extension) is relative to the tour; a bare name is builtin.
  const bool isPath = scene.find('/') != std::string::npos || fs::path(scene).has_extension();
  if (isPath && fs::path(scene).is_relative()) scene = (fs::path(tour.file).parent_path() / scene).string();
  return scene;
}

Scene loadStepScene(const Tour& tour, size_t step, const std::string& assetsDir) {
  const std::string scene = stepScenePath(tour, step);
  try {
    return loadScene(scene, assetsDir);
  } catch (const std::exception& e) {
    throw TourError(tour.file + ": " + describeStep(tour, step) + ".scene: " + e.what());
  }
}

Camera stepCamera(const Tour& tour, size_t step, const Scene& scene) {
  const TourCamera& c = tour.steps.at(step).camera;
  const std::string where = tour.file + ": " + describeStep(tour, step) + ".camera: ";
  Camera base = scene.cameras.front();
  if (c.kind == TourCamera::Kind::Pose) {
    base.name = "tour";
    base.position = c.position;
    base.target = c.target;
    return base;
  }
  if (c.kind == TourCamera::Kind::Path) {
    const CameraPath* path = scene.findPath(c.name);
    if (!path) throw TourError(where + "scene '" + scene.name + "' has no camera path '" + c.name + "'");
    return path->sample(c.pathTime, base);
  }
  if (c.name.empty()) return base;
  if (const Camera* named = scene.findCamera(c.name)) return *named;
  std::vector<std::string> names;
  for (const auto& cam : scene.cameras) names.push_back(cam.name);
  throw TourError(where + "scene '" + scene.name + "' has no camera '" + c.name + "' (cameras: " + joined(names) + ")");
}

}  // namespace sl
