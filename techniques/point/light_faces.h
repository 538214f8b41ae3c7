// Shadow maps of a point light as several perspective faces: the cube's six 90-degree faces and
// the tetrahedron's four (Liao 2010). Each face is fitted to what the camera sees through it (the
// survey's "focus the shadow map" per face), and a face that holds no visible receiver is not
// drawn.
#pragma once

#include "part/part.h"
#include "point/visible_fit.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace sl {

// One face: a perspective view from the light along `axis`, and the directions of the corners of
// the region of the sphere it owns (the directions whose nearest face axis is this one): four
// for a cube face, three for a tetrahedron's.
struct LightFace {
  glm::vec3 axis, up;
  std::vector<glm::vec3> corners;
};
struct FaceSet {
  std::string name;
  std::vector<LightFace> faces;
};
const FaceSet& cubeFaceSet();         // +X, -X, +Y, -Y, +Z, -Z
const FaceSet& tetrahedronFaceSet();  // one face straight down, three tilted 19.47 degrees above the horizon

// The index of the face whose axis is nearest the direction `d` (the largest dot product): the
// face a point reads, as the GLSL module picks it.
int nearestFace(const FaceSet& set, const glm::vec3& d);

// A point layout's views (faces, or the paraboloids' hemispheres) and which of them hold a
// visible receiver.
struct FaceViews {
  LightSpace space;
  std::vector<bool> needed;
  int neededCount() const;
};
// The faces' views for the light (a point light at `light.position`); a face is needed when
// view frustum ∩ scene bounds ∩ its region is not empty. Every face has a view; an undrawn
// face's is its whole region. With `seen` (point.fit_visible: the bounds of the pixels that read
// each face, measured in these same views) a face is needed when a pixel reads it and is cropped
// to those pixels instead. receiversOut: each face's visible receivers (the body it is cropped
// to). fitToView false: every face's view is its whole region (Liao's packing), needed or not.
FaceViews faceViews(const FaceSet& set, const Light& light, const LayoutInput& in,
                    const std::vector<ViewPixelBounds>* seen = nullptr,
                    std::vector<std::vector<glm::vec3>>* receiversOut = nullptr, bool fitToView = true);

// The views widened by `guardTexels` (at most a sixteenth of the layer; none for 2 texels or
// fewer, which the clamped edge texel serves) on every side of their layer: each view draws that
// far past its window, so a filter tap or blocker search that far past a face's edge reads that
// face's own casters instead of the clamped edge texel (beyond the papers; the renderer passes
// the representation's reach, LayoutInput::filterReachTexels).
void widenViews(FaceViews& views, float guardTexels);

// An atlas's squares held between frames (beyond the papers). A square follows its face's need,
// which follows the camera; a square that changed size every frame would change its face's texel
// size, and the edges it draws, every frame: the shimmer of an unsnapped map. So the squares are
// kept while every face's need stays within a factor `band` of the need it was sized for (and
// the same faces are needed, in a layer of the same size and border); beyond it they are sized
// anew. band <= 1: sized anew every frame.
struct AtlasHold {
  std::vector<double> needs;  // what the held squares were sized for
  std::vector<glm::ivec4> squares;
  int size = 0, minSide = 0;
};

// The faces in one atlas layer of shadowmap.size² (beyond the papers: the survey's focusing with
// the texels shared by need): each needed face fitted as faceViews does, then given a square of
// the layer whose area follows its screen footprint (the part of the screen its visible
// receivers cover), with `borderTexels` drawn around its window so filter taps past the window's
// edge read the same face (LightView::atlasRect). Faces no pixel needs get no square.
// hold (a state's memory between frames, null for none): the squares are kept while the faces'
// needs stay within atlas.hold of those they were sized for (heldAtlasSquares).
FaceViews atlasFaceViews(const FaceSet& set, const Light& light, const LayoutInput& in, int borderTexels,
                         const std::vector<ViewPixelBounds>* seen = nullptr, AtlasHold* hold = nullptr);

// Squares for faces of the given needs (>= 0; 0: none) packed in rows into a size x size layer,
// their areas in proportion to the needs, as large as fit, sides multiples of 8 texels of at
// least minSide: x, y, side, side (zero for a need of 0).
std::vector<glm::ivec4> atlasSquares(const std::vector<double>& needs, int size, int minSide);

// atlasSquares, or the held ones while the needs stay within `band` of theirs (AtlasHold).
std::vector<glm::ivec4> heldAtlasSquares(const std::vector<double>& needs, int size, int minSide, double band,
                                         AtlasHold& hold);

// Liao's packing (2010): the four tetrahedron faces drawn into one layer of `size` x `size`
// texels, each into a triangle of it (the square split by its diagonals; LightView::layer,
// ::packedTriangle). A face's region is a triangle in its perspective image (its sides are the
// planes halfway between two face axes), mapped by an affine map onto its triangle of the layer,
// inset by `guardTexels` on every side: the face also draws into that band (up to the triangle's
// edge), so filter taps that reach that far past its region still read its own casters. Faces
// are not fitted to the view (the triangles are fixed); a face with no visible receiver is still
// not drawn.
FaceViews packedTetrahedronViews(const Light& light, const LayoutInput& in, float guardTexels);

// The layer triangle's corners in map NDC ([-1, 1]²) for packed triangle q (0 top, 1 right,
// 2 bottom, 3 left; the centre first), pulled in by `inset` NDC units from every side.
std::array<glm::vec2, 3> packedTriangleCorners(int q, float inset);

// The far plane of a point light's views: the farthest corner of the scene's bounds, or the
// light's range if nearer.
float pointLightFar(const Light& light, const Bounds& bounds);

}  // namespace sl
