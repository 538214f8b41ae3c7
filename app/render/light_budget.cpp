#include "render/light_budget.h"

#include "part/light_frame.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sl {

namespace {

Bounds reachOf(const Light& light, const Bounds& scene) {
  if (light.type != Light::Type::Point || !(light.range > 0.0f)) return scene;
  Bounds b;
  b.min = glm::max(scene.min, light.position - glm::vec3(light.range));
  b.max = glm::min(scene.max, light.position + glm::vec3(light.range));
  return b;
}

}  // namespace

double lightFootprint(const Light& light, const Bounds& sceneBounds, const glm::mat4& view, const glm::mat4& proj,
                      glm::vec4* ndcBounds) {
  if (ndcBounds) *ndcBounds = glm::vec4(-1.0f, -1.0f, 1.0f, 1.0f);
  const Bounds reach = reachOf(light, sceneBounds);
  if (reach.empty()) return 0.0;
  const std::vector<glm::vec3> body = clipFrustumToBox(view, proj, reach);
  if (body.empty()) return 0.0;
  const std::vector<glm::dvec2> ndc = screenPoints(body, proj * view);
  if (ndcBounds && !ndc.empty()) {
    glm::dvec2 lo(1.0), hi(-1.0);
    for (const glm::dvec2& q : ndc) {
      lo = glm::min(lo, q);
      hi = glm::max(hi, q);
    }
    *ndcBounds = glm::vec4(lo.x, lo.y, hi.x, hi.y);
  }
  // A body flat on screen (seen edge-on) still holds visible points: never 0 for a non-empty one.
  return std::clamp(screenShare(ndc), 1e-6, 1.0);
}

glm::ivec4 lightScissor(const Light& light, const glm::vec4& ndcBounds, int width, int height) {
  if (light.type != Light::Type::Point || !(light.range > 0.0f)) return {0, 0, width, height};
  const int x0 = std::clamp(int(std::floor((ndcBounds.x * 0.5f + 0.5f) * width)) - 1, 0, width);
  const int y0 = std::clamp(int(std::floor((ndcBounds.y * 0.5f + 0.5f) * height)) - 1, 0, height);
  const int x1 = std::clamp(int(std::ceil((ndcBounds.z * 0.5f + 0.5f) * width)) + 1, x0, width);
  const int y1 = std::clamp(int(std::ceil((ndcBounds.w * 0.5f + 0.5f) * height)) + 1, y0, height);
  return {x0, y0, x1 - x0, y1 - y0};
}

double heldFootprint(double held, double now, double band) {
  if (!(held > 0.0) || !(now > 0.0)) return now;
  return withinFactor(now, held, band) ? held : now;
}

double budgetedTexels(const std::vector<LightDemand>& lights, const std::vector<int>& sizes) {
  double sum = 0.0;
  for (size_t k = 0; k < lights.size() && k < sizes.size(); ++k)
    sum += double(std::max(lights[k].layers, 1)) * double(sizes[k]) * double(sizes[k]);
  return sum;
}

std::vector<int> budgetMapSizes(const std::vector<LightDemand>& lights, double budgetTexels, int maxSize, int minSize) {
  std::vector<int> sizes(lights.size(), 0);
  std::vector<int> step(lights.size(), 0);  // size = maxSize >> step
  int smallest = 0;
  while ((maxSize >> (smallest + 1)) >= minSize) ++smallest;
  for (size_t k = 0; k < lights.size(); ++k) {
    if (!(lights[k].footprint > 0.0)) continue;
    step[k] = budgetTexels > 0.0 ? smallest : 0;
    sizes[k] = maxSize >> step[k];
  }
  if (!(budgetTexels > 0.0)) return sizes;
  double used = budgetedTexels(lights, sizes);
  for (;;) {
    // The drawn light with the most footprint per texel whose doubling still fits.
    int best = -1;
    double bestNeed = 0.0;
    for (size_t k = 0; k < lights.size(); ++k) {
      if (!sizes[k] || step[k] == 0) continue;
      const double layers = std::max(lights[k].layers, 1);
      const double texels = layers * double(sizes[k]) * sizes[k];
      const double larger = maxSize >> (step[k] - 1);
      if (used - texels + layers * larger * larger > budgetTexels) continue;
      const double need = lights[k].footprint / texels;
      if (need > bestNeed) {
        bestNeed = need;
        best = static_cast<int>(k);
      }
    }
    if (best < 0) break;
    const double layers = std::max(lights[size_t(best)].layers, 1);
    used -= layers * double(sizes[size_t(best)]) * sizes[size_t(best)];
    sizes[size_t(best)] = maxSize >> --step[size_t(best)];
    used += layers * double(sizes[size_t(best)]) * sizes[size_t(best)];
  }
  return sizes;
}

namespace {

// Squares (0: none) placed largest first, bottom-left on a skyline in a layer of side² texels:
// each at the lowest, then leftmost, start of a skyline segment where it fits. Empty when one
// does not fit.
std::vector<glm::ivec4> skylinePack(const std::vector<int>& sides, int side) {
  std::vector<size_t> order(sides.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) { return sides[a] > sides[b]; });
  struct Segment {
    int x, width, y;
  };
  std::vector<Segment> sky = {{0, side, 0}};
  std::vector<glm::ivec4> out(sides.size(), glm::ivec4(0));
  for (size_t i : order) {
    const int s = sides[i];
    if (s <= 0) continue;
    int bestY = side + 1, bestX = 0;
    for (size_t j = 0; j < sky.size() && sky[j].x + s <= side; ++j) {
      int y = 0;
      for (size_t m = j; m < sky.size() && sky[m].x < sky[j].x + s; ++m) y = std::max(y, sky[m].y);
      if (y + s <= side && y < bestY) {
        bestY = y;
        bestX = sky[j].x;
      }
    }
    if (bestY > side) return {};
    out[i] = {bestX, bestY, s, s};
    // The skyline under the square rises to its top.
    std::vector<Segment> next;
    for (const Segment& g : sky) {
      if (g.x < bestX) next.push_back({g.x, std::min(g.width, bestX - g.x), g.y});
      if (g.x + g.width > bestX + s) {
        const int from = std::max(g.x, bestX + s);
        next.push_back({from, g.x + g.width - from, g.y});
      }
    }
    next.push_back({bestX, s, bestY + s});
    std::sort(next.begin(), next.end(), [](const Segment& a, const Segment& b) { return a.x < b.x; });
    sky.clear();
    for (const Segment& g : next) {
      if (!sky.empty() && sky.back().y == g.y)
        sky.back().width += g.width;
      else
        sky.push_back(g);
    }
  }
  return out;
}

}  // namespace

AtlasRegions packAtlasRegions(const std::vector<int>& sides) {
  AtlasRegions out;
  out.rects.assign(sides.size(), glm::ivec4(0));
  int largest = 0;
  double area = 0.0;
  for (int s : sides)
    if (s > 0) {
      largest = std::max(largest, s);
      area += double(s) * double(s);
    }
  if (largest == 0) return out;
  // From the side that holds their area upward, 8 texels at a time: the first that holds them
  // all (a row of them always does).
  for (int side = (std::max(largest, static_cast<int>(std::ceil(std::sqrt(area)))) + 7) / 8 * 8;; side += 8) {
    std::vector<glm::ivec4> rects = skylinePack(sides, side);
    if (!rects.empty()) {
      out.side = side;
      out.rects = std::move(rects);
      return out;
    }
  }
}

namespace {

// The next size above `size` on the ladder of halvings of `top` (top >> j, as the budget makes
// them: 627 above 313 under 2508, not 626).
int ladderStepAbove(int top, int size) {
  int larger = top;
  while ((larger >> 1) > size) larger >>= 1;
  return larger;
}

}  // namespace

std::vector<int> fillAtlasSizes(const std::vector<LightDemand>& lights, std::vector<int> sizes,
                                std::vector<bool>& inAtlas) {
  auto sidesOf = [&](const std::vector<int>& s) {
    std::vector<int> sides(s.size(), 0);
    for (size_t k = 0; k < s.size() && k < inAtlas.size(); ++k) sides[k] = inAtlas[k] ? s[k] : 0;
    return sides;
  };
  const int side = packAtlasRegions(sidesOf(sizes)).side;
  if (side > kMaxOneAtlasSide) {
    inAtlas.assign(inAtlas.size(), false);
    return sizes;
  }
  int cell = 0;
  for (int s : sidesOf(sizes)) cell = std::max(cell, s);
  for (;;) {
    int best = -1;
    double bestNeed = 0.0;
    for (size_t k = 0; k < sizes.size() && k < lights.size() && k < inAtlas.size(); ++k) {
      if (!inAtlas[k] || sizes[k] <= 0 || sizes[k] >= cell) continue;
      std::vector<int> trial = sizes;
      trial[k] = ladderStepAbove(cell, sizes[k]);
      if (skylinePack(sidesOf(trial), side).empty()) continue;
      const double need = lights[k].footprint / (double(sizes[k]) * sizes[k]);
      if (need > bestNeed) {
        bestNeed = need;
        best = static_cast<int>(k);
      }
    }
    if (best < 0) return sizes;
    sizes[size_t(best)] = ladderStepAbove(cell, sizes[size_t(best)]);
  }
}

}  // namespace sl
