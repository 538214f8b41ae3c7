// Geometry shared by the layouts: the light's view basis and the convex body of points a
// focused shadow map must cover (Brabec et al. 2002: view frustum clipped to the scene).
#pragma once

#include "part/part.h"

#include <vector>

namespace sl {

// Light view matrix: fixed basis for a directional light (independent of the camera so that
// snapping can keep texels still), apex at the light for a spot; rotated by `roll` about the
// light's forward axis (pixel-correct jitter).
glm::mat4 lightViewMatrix(const Light& light, float roll);

// The light moved to `diskPoint` (unit disk) of its area: spot, the apex moved by radius in the
// disk's plane; directional, the direction tilted by radius (tan of the angular radius).
Light sampledLight(const Light& light, glm::vec2 diskPoint);
// The light a layout builds its views from: the scene's, at the jitter's light sample. A point
// light becomes a spot at its position aimed at the visible receivers (the survey's fitting for
// a point light: one frustum around what the camera sees), its cone as wide as they need up to
// 2 * kPointAsSpotMaxHalfDeg; beyond that the single-frustum layouts miss receivers, which is
// what the cube layout (techniques/point/light_faces.h) is for.
Light layoutLight(const LayoutInput& in);
inline constexpr float kPointAsSpotMaxHalfDeg = 80.0f;
Light pointAsSpot(const Light& point, const std::vector<glm::vec3>& receivers);

// The 8 world-space corners of the camera frustum.
std::vector<glm::vec3> frustumCorners(const glm::mat4& view, const glm::mat4& proj);

// Vertices of (camera frustum ∩ box); empty when they do not intersect.
std::vector<glm::vec3> clipFrustumToBox(const glm::mat4& view, const glm::mat4& proj, const Bounds& box);
// The same for any convex body given as 8 corners indexed x + 2y + 4z (bits) like a frustum's;
// corners may coincide (a pyramid: the faces that collapse clip nothing away).
std::vector<glm::vec3> clipCornersToBox(const std::vector<glm::vec3>& corners, const Bounds& box);
// The same clipped by half-spaces dot(xyz, p) + w >= 0.
std::vector<glm::vec3> clipCornersToPlanes(const std::vector<glm::vec3>& corners, const std::vector<glm::vec4>& planes);
// The half-spaces of a box, and of a view-projection's clip volume (-w <= x, y, z <= w).
std::vector<glm::vec4> boxPlanes(const Bounds& box);
std::vector<glm::vec4> frustumPlanes(const glm::mat4& viewProj);

std::vector<glm::vec3> boxCorners(const Bounds& b);

// Orthographic fit: window and depth range in light view space, snapping, jitter, matrices.
// `receivers` bound the window; `casters` extend the near plane toward the light.
LightView fitOrthographic(const glm::mat4& lightView, const std::vector<glm::vec3>& receivers,
                          const std::vector<glm::vec3>& casters, int size, bool snap, const LayoutJitter& jitter);

// Perspective (spot) fit: the cone, optionally cropped to the receivers' projection.
// squareTexels false: the crop's window fits each axis on its own (texels longer along one axis
// where the receivers' projection is longer along it; texelWorldSize is the longer side's).
LightView fitPerspective(const Light& light, const glm::mat4& lightView, const std::vector<glm::vec3>& receivers,
                         const std::vector<glm::vec3>& casters, int size, bool crop, bool snap,
                         const LayoutJitter& jitter, bool squareTexels = true);

// What the fitted layouts start from: the scene's bounds and corners (the casters), the visible
// receivers (view frustum ∩ bounds; the corners when the view misses the scene), the light view
// (with the jitter's roll) and the texels per side.
struct FocusBody {
  Bounds bounds;
  std::vector<glm::vec3> casters, receivers;
  glm::mat4 lightView{1.0f};
  int size = 1024;
};
FocusBody focusBody(const LayoutInput& in);
// The focused map of that body (Brabec et al. 2002), unsnapped: what the warped layouts fall back
// to for spot lights and degenerate views.
LightSpace focusedMap(const LayoutInput& in, const FocusBody& body);

// The convex hull, in `view`'s map uv, of the convex body with corners `receivers`
// (LightView::receiverHull), clipped to its part in front of the light; empty when all of it is
// behind, or the view bends its projection (LogPSM, paraboloid), where a hull of the corners
// would not hold the body.
std::vector<glm::vec2> receiverHullInMap(const LightView& view, const std::vector<glm::vec3>& receivers);
// The convex hull of points (counter-clockwise, no repeated or collinear vertices).
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points);
std::vector<glm::dvec2> convexHull(std::vector<glm::dvec2> points);

// Whether `now` is within a factor `band` (>= 1) of `was`, either way: the hysteresis that keeps
// an allocation (a light's map size, an atlas's squares) while what it was sized for drifts.
inline bool withinFactor(double now, double was, double band) { return now <= was * band && now * band >= was; }

// A convex body's corners on screen: the NDC of those in front of the camera, clamped to the
// screen [-1, 1]² (a corner on the camera's plane by rounding is left out: the body's other
// corners bound it).
std::vector<glm::dvec2> screenPoints(const std::vector<glm::vec3>& body, const glm::mat4& viewProj);
// The share of the screen (0..1) the convex hull of such points covers.
double screenShare(const std::vector<glm::dvec2>& ndc);

// Snapping: texel size taken from a geometric ladder (8 steps per octave) so it stays constant
// while the fitted extent changes a little, and the window origin on whole texels.
float quantizeTexelSize(float texel);

// Where a world point falls in a light view: map uv (layer 0) and stored (linear) depth.
// False when it is behind the view.
bool mapPointOf(const glm::vec3& world, const LightView& view, glm::vec3& uvLayer, float& depth);

// World point at stored depth d on the light ray through map position uv of `view`.
glm::vec3 lightRayPoint(const LightView& view, glm::vec2 uv, float d);

}  // namespace sl
