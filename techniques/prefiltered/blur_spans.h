// Which texels of a moment map the blur must filter: those a visible receiver can read. A view's
// receiver hull (LightView::receiverHull, map uv) bounds where visible receivers fall; the blur
// runs only the work groups whose texels lookups near the hull read, and those that the second
// direction's kernel reads from the first (beyond the papers).
#pragma once

#include <glm/glm.hpp>

#include <optional>
#include <vector>

namespace sl {

// The blur's geometry (passes/moment_blur.comp): an invocation filters a run of kBlurRun texels
// along its direction, a work group kBlurGroupSide runs along it by kBlurGroupSide lines across.
inline constexpr int kBlurRun = 8;
inline constexpr int kBlurGroupSide = 8;
// Texels around a receiver's map position that its lookup reads: a bilinear tap reads the
// texels whose centres lie within one texel; one more for the rounding of the hull's corners.
inline constexpr float kLookupReach = 2.0f;

// The convex polygon `hullUv` (map uv) of a size² map in texel units (texel i spans [i, i + 1)),
// dilated by `dilation` texels along both axes (the Minkowski sum with a square).
std::vector<glm::vec2> dilatedHull(const std::vector<glm::vec2>& hullUv, int size, float dilation);

// Per band of `band` rows of a size² map, the columns [x, y] that the convex polygon `texels`
// (texel units, as dilatedHull gives it) covers in any row of the band; {1, 0} where it misses.
std::vector<glm::ivec2> polygonSpans(const std::vector<glm::vec2>& texels, int size, int band);

// Per band of `band` rows of a size² map, the columns [x, y] that the convex polygon `hullUv`
// (map uv) dilated by `dilation` texels covers in any row of the band; {1, 0} where it misses
// the band. An empty hull covers every texel.
std::vector<glm::ivec2> blurSpans(const std::vector<glm::vec2>& hullUv, int size, int band, float dilation);

// Per column of a size² map, the rows [y0, y1] whose span (rowSpans, per row [x0, x1]; x0 > x1:
// none) holds it ({1, 0}: none); std::nullopt where some column's rows are not one interval (the
// spans of a convex region never are: the summed-area tables' column pass needs intervals).
std::optional<std::vector<glm::ivec2>> columnIntervals(const std::vector<glm::ivec2>& rowSpans, int size);

// The work groups each direction of a blur with `apron` texels each side runs (x: the group
// along its runs, y: across them, as a full dispatch numbers them) so that every texel of
// `spans` (bands of kBlurRun rows) comes out filtered: the second direction's groups that hold
// one, the first direction's groups that hold what those read. `share`: the fraction of the map
// the second direction's groups make.
struct BlurGroups {
  std::vector<glm::uvec2> first, second;
  double share = 1.0;
};
BlurGroups blurGroups(const std::vector<glm::ivec2>& spans, int size, int apron);

}  // namespace sl
