#include "point/light_faces.h"

#include "part/light_frame.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sl {

namespace {

// A cube face's corners in the order of a frustum's (x + 2y bits of the face's right and up).
LightFace cubeFace(const glm::vec3& axis, const glm::vec3& up) {
  const glm::vec3 right = glm::normalize(glm::cross(axis, up));
  const glm::vec3 trueUp = glm::cross(right, axis);
  LightFace f{axis, up, {}};
  for (int y = -1; y <= 1; y += 2)
    for (int x = -1; x <= 1; x += 2) f.corners.push_back(axis + float(x) * right + float(y) * trueUp);
  return f;
}

FaceSet makeCube() {
  return {"cube",
          {cubeFace({1, 0, 0}, {0, -1, 0}), cubeFace({-1, 0, 0}, {0, -1, 0}), cubeFace({0, 1, 0}, {0, 0, 1}),
           cubeFace({0, -1, 0}, {0, 0, -1}), cubeFace({0, 0, 1}, {0, -1, 0}), cubeFace({0, 0, -1}, {0, -1, 0})}};
}

// A regular tetrahedron's face normals: one straight down (a lamp's ground in one face), three
// 19.47 degrees above the horizon, 120 degrees apart; any two at dot -1/3. The corners of face i's
// region are the tetrahedron's vertices seen from its centre, -n_j for j != i.
FaceSet makeTetrahedron() {
  const float s = std::sqrt(8.0f) / 3.0f;
  std::vector<glm::vec3> normals = {{0, -1, 0}};
  for (int k = 0; k < 3; ++k) {
    const float a = glm::radians(90.0f + 120.0f * k);
    normals.push_back({s * std::cos(a), 1.0f / 3.0f, s * std::sin(a)});
  }
  FaceSet set{"tetrahedron", {}};
  for (size_t i = 0; i < normals.size(); ++i) {
    LightFace f{normals[i], i == 0 ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0), {}};
    for (size_t j = 0; j < normals.size(); ++j)
      if (j != i) f.corners.push_back(-normals[j]);
    set.faces.push_back(f);
  }
  return set;
}

// The body a face owns between two distances along its axis, as 8 corners indexed like a
// frustum's (a triangle's third corner doubled: clipCornersToPlanes accepts collapsed faces).
std::vector<glm::vec3> faceRegion(const LightFace& face, const glm::vec3& apex, float near, float far) {
  std::vector<glm::vec3> dirs = face.corners;
  if (dirs.size() == 3) dirs.push_back(dirs[2]);
  std::vector<glm::vec3> out;
  for (float dist : {near, far})
    for (const glm::vec3& d : dirs) out.push_back(apex + d * (dist / glm::dot(d, face.axis)));
  return out;
}

// The square field of view (degrees) that holds the face's region in `view` (its roll included).
float enclosingFovDeg(const LightFace& face, const glm::mat4& view) {
  float halfTan = 0.0f;
  for (const glm::vec3& c : face.corners) {
    const glm::vec3 v = glm::mat3(view) * c;
    halfTan = std::max({halfTan, std::abs(v.x / -v.z), std::abs(v.y / -v.z)});
  }
  return glm::degrees(2.0f * std::atan(halfTan * 1.0001f));
}

}  // namespace

float pointLightFar(const Light& light, const Bounds& bounds) {
  float far = 0.0f;
  for (const glm::vec3& c : boxCorners(bounds)) far = std::max(far, glm::length(c - light.position));
  if (light.range > 0.0f) far = std::min(far, light.range);
  return std::max(far * 1.01f, 1e-3f);
}

const FaceSet& cubeFaceSet() {
  static const FaceSet set = makeCube();
  return set;
}

const FaceSet& tetrahedronFaceSet() {
  static const FaceSet set = makeTetrahedron();
  return set;
}

int nearestFace(const FaceSet& set, const glm::vec3& d) {
  int best = 0;
  for (int f = 1; f < static_cast<int>(set.faces.size()); ++f)
    if (glm::dot(d, set.faces[f].axis) > glm::dot(d, set.faces[best].axis)) best = f;
  return best;
}

int FaceViews::neededCount() const { return static_cast<int>(std::count(needed.begin(), needed.end(), true)); }

FaceViews faceViews(const FaceSet& set, const Light& light, const LayoutInput& in,
                    const std::vector<ViewPixelBounds>* seen, std::vector<std::vector<glm::vec3>>* receiversOut,
                    bool fitToView) {
  const Bounds bounds = in.scene->boundsAt(in.time);
  const int size = in.params->i("shadowmap.size");
  const bool snap = in.params->b("layout.snap");
  const float far = pointLightFar(light, bounds);
  // A near plane this close keeps casters touching the light in the map; stored depth is linear,
  // so it costs no precision.
  const float near = far * 1e-4f;
  std::vector<glm::vec4> frustum = frustumPlanes(in.cameraProj * in.cameraView);
  const std::vector<glm::vec4> box = boxPlanes(bounds);
  frustum.insert(frustum.end(), box.begin(), box.end());
  Light faceLight = light;
  faceLight.type = Light::Type::Spot;
  FaceViews out;
  out.space.views.clear();  // a LightSpace starts with one view
  out.space.size = size;
  for (size_t f = 0; f < set.faces.size(); ++f) {
    const LightFace& face = set.faces[f];
    faceLight.direction = face.axis;
    glm::mat4 view = glm::lookAt(light.position, light.position + face.axis, face.up);
    if (in.jitter.rotationRad != 0.0f)
      view = glm::rotate(glm::mat4(1.0f), in.jitter.rotationRad, glm::vec3(0, 0, 1)) * view;
    faceLight.fovDeg = enclosingFovDeg(face, view);
    const std::vector<glm::vec3> region = faceRegion(face, light.position, near, far);
    std::vector<glm::vec3> receivers = clipCornersToPlanes(region, frustum);
    if (seen && f < seen->size())
      receivers = (*seen)[f].valid ? pixelBoundsCorners((*seen)[f], view, size) : std::vector<glm::vec3>{};
    std::vector<glm::vec3> casters = clipCornersToPlanes(region, box);
    const bool needed = !receivers.empty();
    out.needed.push_back(needed);
    if (receiversOut) receiversOut->push_back(receivers);
    if (casters.empty()) casters = region;
    const bool crop = needed && fitToView;
    out.space.views.push_back(fitPerspective(faceLight, view, crop ? receivers : region, casters, size, crop, snap,
                                             in.jitter,
                                             /*squareTexels=*/seen == nullptr));
  }
  return out;
}

namespace {

// The 2D affine map taking triangle `from` onto triangle `to`, as a matrix on clip positions
// (x and y mixed with w, so it holds after the perspective divide; z and w unchanged).
glm::mat4 affineOnClip(const std::array<glm::vec2, 3>& from, const std::array<glm::vec2, 3>& to) {
  const glm::mat3 f(glm::vec3(from[0], 1.0f), glm::vec3(from[1], 1.0f), glm::vec3(from[2], 1.0f));
  const glm::mat3 t(glm::vec3(to[0], 1.0f), glm::vec3(to[1], 1.0f), glm::vec3(to[2], 1.0f));
  const glm::mat3 m = t * glm::inverse(f);  // columns: x, y, translation
  glm::mat4 a(1.0f);
  a[0][0] = m[0][0];
  a[0][1] = m[0][1];
  a[1][0] = m[1][0];
  a[1][1] = m[1][1];
  a[3][0] = m[2][0];
  a[3][1] = m[2][1];
  return a;
}

float signedArea(const std::array<glm::vec2, 3>& t) {
  const glm::vec2 a = t[1] - t[0], b = t[2] - t[0];
  return a.x * b.y - a.y * b.x;
}

}  // namespace

std::array<glm::vec2, 3> packedTriangleCorners(int q, float inset) {
  // The top triangle, y >= |x|: its incircle has radius r = sqrt(2) - 1 about (0, 1 - r); moving
  // every side in by `inset` scales it about that centre by (r - inset) / r.
  const float r = std::sqrt(2.0f) - 1.0f;
  const glm::vec2 centre(0.0f, 1.0f - r);
  const float scale = std::max(r - inset, 0.05f * r) / r;
  std::array<glm::vec2, 3> top = {glm::vec2(0.0f, 0.0f), glm::vec2(1.0f, 1.0f), glm::vec2(-1.0f, 1.0f)};
  for (glm::vec2& c : top) {
    c = centre + (c - centre) * scale;
    // Turned from the top onto triangle q (the inverse of shaders/common/light_views.glsl's turn).
    if (q == 1) c = glm::vec2(c.y, -c.x);
    if (q == 2) c = -c;
    if (q == 3) c = glm::vec2(-c.y, c.x);
  }
  return top;
}

FaceViews packedTetrahedronViews(const Light& light, const LayoutInput& in, float guardTexels) {
  const FaceSet& set = tetrahedronFaceSet();
  FaceViews out = faceViews(set, light, in, nullptr, nullptr, /*fitToView=*/false);
  const float inset = 2.0f * std::max(guardTexels, 0.0f) / float(std::max(out.space.size, 1));
  for (size_t f = 0; f < set.faces.size(); ++f) {
    LightView& v = out.space.views[f];
    // The region's corners in the face's image, onto the layer's triangle f, keeping the turn
    // (a mirrored map would swap the casters' front and back faces).
    std::array<glm::vec2, 3> from;
    for (size_t k = 0; k < 3; ++k) {
      const glm::vec4 c = v.viewProj * glm::vec4(light.position + set.faces[f].corners[k], 1.0f);
      from[k] = glm::vec2(c) / c.w;
    }
    std::array<glm::vec2, 3> to = packedTriangleCorners(static_cast<int>(f), inset);
    if ((signedArea(from) > 0.0f) != (signedArea(to) > 0.0f)) std::swap(to[1], to[2]);
    v.proj = affineOnClip(from, to) * v.proj;
    v.viewProj = v.proj * v.view;
    // Texel size at unit distance: the face's, over the map's linear scale (sqrt of its area ratio).
    v.texelWorldSize /= std::sqrt(std::abs(signedArea(to) / signedArea(from)));
    v.layer = 0;
    v.packedTriangle = static_cast<int>(f);
  }
  return out;
}

namespace {

// Squares of the given sides (0: none) in rows of a size x size layer, largest first; empty when
// they do not fit.
std::vector<glm::ivec4> shelfPack(const std::vector<int>& sides, int size) {
  std::vector<size_t> order(sides.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sides[a] > sides[b]; });
  std::vector<glm::ivec4> out(sides.size(), glm::ivec4(0));
  int x = 0, y = 0, rowHeight = 0;
  for (size_t i : order) {
    const int s = sides[i];
    if (s <= 0) continue;
    if (x + s > size) {  // next row
      y += rowHeight;
      x = 0;
      rowHeight = 0;
    }
    if (s > size || y + s > size) return {};
    out[i] = {x, y, s, s};
    x += s;
    rowHeight = std::max(rowHeight, s);
  }
  return out;
}

}  // namespace

std::vector<glm::ivec4> atlasSquares(const std::vector<double>& needs, int size, int minSide) {
  double total = 0.0;
  for (double n : needs) total += std::max(n, 0.0);
  std::vector<glm::ivec4> none(needs.size(), glm::ivec4(0));
  if (!(total > 0.0) || size < 8) return none;
  // Shrink every square together until the rows hold them (a square of the layer's whole area
  // never fits in rows unless it is one square).
  for (double k = 1.0; k > 0.01; k *= 0.97) {
    std::vector<int> sides;
    for (double n : needs) {
      if (!(n > 0.0)) {
        sides.push_back(0);
        continue;
      }
      const int side = static_cast<int>(k * size * std::sqrt(n / total)) / 8 * 8;
      sides.push_back(std::min(std::max(side, std::min(minSide, size)), size));
    }
    std::vector<glm::ivec4> packed = shelfPack(sides, size);
    if (!packed.empty()) return packed;
  }
  // A layer too small for the smallest side asked: the smallest squares there are.
  return minSide > 8 ? atlasSquares(needs, size, 8) : none;
}

void widenViews(FaceViews& views, float guardTexels) {
  const float size = static_cast<float>(views.space.size);
  // A tap a couple of texels past the edge reads the clamped edge texel, which sees nearly the
  // same direction: a 3-texel border changed nothing for PCF (seams.md), and costs resolution.
  if (!(guardTexels > 2.0f)) return;
  const float guard = std::min(std::ceil(guardTexels), size / 16.0f);
  const float k = (size - 2.0f * guard) / size;  // the window's share of the layer
  glm::mat4 shrink(1.0f);
  shrink[0][0] = shrink[1][1] = k;
  for (LightView& v : views.space.views) {
    v.proj = shrink * v.proj;
    v.viewProj = v.proj * v.view;
    v.texelWorldSize /= k;
    const glm::vec2 centre = 0.5f * (v.windowMin + v.windowMax), half = 0.5f * (v.windowMax - v.windowMin) / k;
    v.windowMin = centre - half;
    v.windowMax = centre + half;
  }
}

std::vector<glm::ivec4> heldAtlasSquares(const std::vector<double>& needs, int size, int minSide, double band,
                                         AtlasHold& hold) {
  bool keep = band > 1.0 && hold.size == size && hold.minSide == minSide && hold.needs.size() == needs.size();
  for (size_t f = 0; keep && f < needs.size(); ++f) {
    const double was = hold.needs[f], now = needs[f];
    keep = (was > 0.0) == (now > 0.0) && (!(now > 0.0) || withinFactor(now, was, band));
  }
  if (keep) return hold.squares;
  hold = {.needs = needs, .squares = atlasSquares(needs, size, minSide), .size = size, .minSide = minSide};
  return hold.squares;
}

FaceViews atlasFaceViews(const FaceSet& set, const Light& light, const LayoutInput& in, int borderTexels,
                         const std::vector<ViewPixelBounds>* seen, AtlasHold* hold) {
  std::vector<std::vector<glm::vec3>> receivers;
  FaceViews out = faceViews(set, light, in, seen, &receivers);
  const int size = out.space.size;
  // The border: atlas.border, or what the representation's taps read past the window (its
  // reach) where that is more, but at most an eighth of a square's side (below).
  const int border = std::clamp(borderTexels, 0, size / 8);
  const int reach = static_cast<int>(std::ceil(in.filterReachTexels));
  const glm::mat4 camera = in.cameraProj * in.cameraView;
  std::vector<double> needs;
  for (size_t f = 0; f < out.space.views.size(); ++f)
    needs.push_back(out.needed[f] && f < receivers.size() && !receivers[f].empty()
                        ? std::max(screenShare(screenPoints(receivers[f], camera)), 1e-4)
                        : 0.0);
  const double band = in.params && in.params->has("atlas.hold") ? in.params->get("atlas.hold") : 1.0;
  const std::vector<glm::ivec4> squares =
      hold ? heldAtlasSquares(needs, size, 2 * border + 16, band, *hold) : atlasSquares(needs, size, 2 * border + 16);
  for (size_t f = 0; f < out.space.views.size(); ++f) {
    LightView& v = out.space.views[f];
    v.layer = 0;
    const glm::ivec4 sq = squares[f];
    if (sq.z <= 0) {  // not needed (or no room): not drawn, and no pixel reads it
      out.needed[f] = false;
      continue;
    }
    // The fitted window onto the square's inside; the border around it is drawn too (narrower
    // in a square too small for it). A reach past atlas.border widens it up to an eighth of the
    // side: a small square keeps most of its texels for its face (taps further out are clamped
    // to the square, lightViewTap).
    const int squareBorder = std::max(border, std::min(reach, sq.z / 8));
    const float inner = float(sq.z - 2 * std::min(squareBorder, std::max(0, (sq.z - 8) / 2)));
    v.proj = squareOntoRect(sq, inner, size) * v.proj;
    v.viewProj = v.proj * v.view;
    v.texelWorldSize *= float(size) / inner;
    v.atlasRect = sq;
  }
  return out;
}

}  // namespace sl
