// JSON and CSV output of `shadowlab bench`; see bench.h and docs/benchmarks.md.
#include "bench/bench.h"

#include <cstdlib>
#include <fstream>
#include <stdexcept>

namespace sl {

namespace {

using nlohmann::json;

json visibilityErrorJson(const ErrorMetrics& m) {
  return {{"wrong_pixel_pct", m.wrongPixelPct},
          {"false_shadow_pct", m.falseShadowPct},
          {"false_light_pct", m.falseLightPct},
          {"rmse", m.rmse}};
}

// The other lights of the scene, numbered as in the file's list after the first shadowed one.
json otherLightsJson(const std::vector<BenchEntry::LightError>& lights) {
  json out = json::array();
  for (size_t k = 0; k < lights.size(); ++k) {
    json one = {{"light", k + 2}, {"shadowed", lights[k].shadowed}};
    if (lights[k].shadowed) one.update(visibilityErrorJson(lights[k].error));
    out.push_back(one);
  }
  return out;
}

json entryJson(const BenchEntry& e) {
  json x;
  x["technique"] = e.technique;
  x["label"] = e.label;
  x["params"] = json::object();
  for (const auto& [k, v] : e.params) x["params"][k] = v;
  x["sweep"] = json::object();
  for (const auto& [k, v] : e.sweepPoint) x["sweep"][k] = v;
  x["frames"] = e.frames;
  x["timer"] = e.timer;
  x["ms_per_frame"] = {{"median", e.msMedian}, {"p95", e.msP95}, {"frames", e.frameMs}};
  x["ms_ratio"] = {{"median", e.msRatio}, {"p25", e.msRatioP25}, {"p75", e.msRatioP75}};
  x["passes"] = json::array();
  for (const auto& p : e.passes) x["passes"].push_back({{"name", p.name}, {"ms", p.ms}});
  x["error"] = visibilityErrorJson(e.error);
  x["error"].update({{"image_wrong_pct", e.image.imageWrongPct}, {"valid_pixels", e.error.validPixels}});
  if (!e.otherLights.empty()) x["error"]["other_lights"] = otherLightsJson(e.otherLights);
  x["convergence"] = e.convergence;
  if (e.hasFlicker)
    x["flicker"] = {{"excess", e.flicker},
                    {"technique", e.flickerTechnique},
                    {"reference", e.flickerReference},
                    {"world", e.worldFlicker}};
  else
    x["flicker"] = nullptr;
  x["nonfinite_pixels"] = e.nonfinite;
  x["shadow_texels"] = e.shadowTexels;
  if (!e.status.empty()) x["status"] = e.status;
  return x;
}

}  // namespace

nlohmann::json benchToJson(const BenchResult& r) {
  using nlohmann::json;
  json j;
  j["scene"] = r.sceneName;
  j["size"] = {r.options.width, r.options.height};
  if (!r.options.path.empty()) {
    j["path"] = r.options.path;
    j["camera"] = nullptr;
  } else {
    j["camera"] = r.options.camera;
    j["path"] = nullptr;
  }
  j["time"] = r.options.time;
  j["renderer"] = r.renderer;
  j["timer"] = r.timer;
  j["machine"] = {{"cores", r.cores}, {"cpu", r.cpu}};
  j["date"] = r.date;
  j["command"] = r.options.commandLine;
  j["provenance"] = {{"commit", r.commit.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.commit)},
                     {"dirty", r.dirty},
                     {"build_type", r.buildType}};
  // Shaders are read at run time: a run with another folder's shaders says so (an A/B of shader
  // versions under one build has the same commit on both sides).
  if (const char* shaders = std::getenv("SHADOWLAB_SHADERS")) j["provenance"]["shaders"] = shaders;
  j["warmup"] = r.options.warmup;
  // Entries are rendered in turn at each frame index; ms_ratio is relative to the first entry.
  j["timing_order"] = "interleaved";
  j["ms_ratio_baseline"] = r.entries.empty() ? nlohmann::json(nullptr) : nlohmann::json(r.entries.front().label);
  j["approach_frames"] = r.options.approach;
  j["approach_deg"] = r.options.approachDeg;
  j["reference"] = {{"samples_per_pixel", r.referenceSamples},
                    {"traced", r.referencesTraced},
                    {"cached", r.referencesCached},
                    {"trace_ms_total", r.referenceTraceMs}};
  if (!r.options.path.empty()) j["reference"]["flicker"] = r.referenceFlicker;
  j["shader_errors"] = r.shaderErrors;
  j["entries"] = json::array();
  for (const auto& e : r.entries) j["entries"].push_back(entryJson(e));
  return j;
}

static std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

void writeBenchCsv(const BenchResult& r, const std::string& file) {
  std::ofstream f(file);
  if (!f) throw std::runtime_error(file + ": cannot write");
  std::string sweepKeys;
  f << "label,technique,sweep,ms_median,ms_p95,ms_ratio,ms_ratio_p25,ms_ratio_p75,wrong_pixel_pct,false_shadow_pct,"
       "false_light_pct,image_wrong_pct,rmse,flicker_excess,flicker_world,nonfinite_pixels,frames,timer\n";
  for (const auto& e : r.entries) {
    std::string sweep;
    for (const auto& [k, v] : e.sweepPoint) sweep += (sweep.empty() ? "" : " ") + k + "=" + v;
    f << csvField(e.label) << "," << csvField(e.technique) << "," << csvField(sweep) << "," << e.msMedian << ","
      << e.msP95 << "," << e.msRatio << "," << e.msRatioP25 << "," << e.msRatioP75 << "," << e.error.wrongPixelPct
      << "," << e.error.falseShadowPct << "," << e.error.falseLightPct << "," << e.image.imageWrongPct << ","
      << e.error.rmse << "," << (e.hasFlicker ? std::to_string(e.flicker) : std::string()) << ","
      << (e.hasFlicker ? std::to_string(e.worldFlicker) : std::string()) << "," << e.nonfinite << "," << e.frames << ","
      << e.timer << "\n";
  }
}

}  // namespace sl
