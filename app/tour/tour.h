// Lecture tours (docs/tour-format.md): a JSON file of steps, each a scene, a camera, 1..4
// viewports (a preset with overrides and the debug views shown) and a caption, replayed in the
// explorer (--tour) or rendered as figures (`shadowlab figure`). Parsing is strict and needs no
// GL context or file access, so a fuzzer can call parseTour on any text.
#pragma once

#include "scene/scene.h"

#include <glm/glm.hpp>

#include <stdexcept>
#include <string>
#include <vector>

namespace sl {

// Thrown for any bad tour; what() names the tour file, the step and the field.
class TourError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The view every viewport may list: its visibility against the ray-traced reference (grey agree,
// orange false shadow, blue false light; app/metrics errorImage), as the explorer's accuracy
// panel and figures draw it.
constexpr const char* kErrorView = "error";

struct TourViewport {
  std::string technique;               // preset id (possibly a planned one, see TourStep::missing)
  std::vector<std::string> overrides;  // "key=value", validated against the preset's declarations
  std::vector<std::string> views;      // debug views shown beside the colour image
  std::string label;                   // panel title ("" = the preset id)
  std::string enlarged;                // one of `views` shown large in the tile instead of thumbnails ("" = none)
};

// Which camera a step looks through: a named scene camera (default: the scene's first), an
// explicit pose, or a named camera path sampled at `pathTime` seconds.
struct TourCamera {
  enum class Kind { Scene, Pose, Path };
  Kind kind = Kind::Scene;
  std::string name;  // Scene: camera name ("" = first); Path: path name
  glm::vec3 position{0.0f}, target{0.0f};
  float pathTime = 0.0f;
};

// An optional plot beside the figure, made by `shadowlab plot` on the step's scene and camera.
struct TourPlot {
  enum class Kind { None, Dpds, Visibility };
  Kind kind = Kind::None;
  std::vector<std::string> techniques;  // dpds: "preset[:key=v;key=v]"; visibility: pre-filtered presets
  glm::ivec2 pixel{-1, -1};             // visibility: screen pixel from the bottom left (-1: centre)
  glm::vec2 point{-1.0f, -1.0f};        // or that pixel as shares of the panel's width and height (any size)
};

// A comparison the step's caption makes, checked against the ray-traced reference (wrong pixels,
// or false light or shadow, app/metrics) by TourClaims tests and `shadowlab figure --check`:
// - Better: viewport `viewport` has at most 1/factor of viewport `than`'s wrong pixels at the
//   step's last frame (viewports numbered from 1, as in figures);
// - Converges: viewport `viewport` has at most 1/factor of its own wrong pixels at the step's
//   first captured frame by its last.
struct TourClaim {
  enum class Kind { Better, Converges };
  // What is counted: wrong pixels, or only those lit where the truth is shadowed (leaks), or only
  // those shadowed where it is lit ("metric": "wrong", "false_light", "false_shadow"); or pixels
  // whose colour differs from the reference's ("image_wrong": every light of the scene counts).
  enum class Metric { Wrong, FalseLight, FalseShadow, ImageWrong };
  Kind kind = Kind::Better;
  Metric metric = Metric::Wrong;
  int viewport = 1, than = 0;
  double factor = 1.0;
};

struct TourStep {
  std::string title, caption;
  std::string scene = "basic";  // builtin id or path (relative paths: from the tour file)
  TourCamera camera;
  bool setLight = false;
  glm::vec2 lightAngles{0.0f};  // degrees, as --light AZ,EL
  std::vector<TourViewport> viewports;
  std::vector<int> frames{1};  // still-camera frame counts captured (increasing, >= 1)
  TourPlot plot;
  std::vector<TourClaim> claims;
  // Planned presets this step names that the registry does not have yet ("requires"): the step
  // is kept, not rendered, and its caption says so.
  std::vector<std::string> missing;
  bool built() const { return missing.empty(); }
  std::string shownCaption() const;  // the caption, prefixed with "Not built yet: ..." when !built()
};

struct Tour {
  std::string file;  // where it came from (for messages and relative scene paths)
  std::string title;
  std::vector<TourStep> steps;  // at least one
};

// Parses and validates a tour. Throws TourError naming `fileName`, the step index and title, and
// the field: bad JSON, unknown keys, unknown presets (unless listed in the step's "requires"),
// bad parameter overrides, views the technique does not offer, bad frames or plot.
Tour parseTour(const std::string& text, const std::string& fileName);
// Reads and parses a tour file; throws TourError for a missing or unreadable file too.
Tour loadTour(const std::string& path);
// The scene id or path a step names (a relative path resolved against the tour file's folder).
std::string stepScenePath(const Tour& tour, size_t step);
// The scene a step names, resolved against the tour file's folder and the assets folder; throws
// TourError naming the step for a scene that does not load.
Scene loadStepScene(const Tour& tour, size_t step, const std::string& assetsDir);
// The step's camera in its scene; throws TourError naming the step for an unknown camera/path.
Camera stepCamera(const Tour& tour, size_t step, const Scene& scene);
// "steps[3] (\"Title\")": how messages name a step.
std::string describeStep(const Tour& tour, size_t step);

}  // namespace sl
