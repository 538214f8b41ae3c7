#pragma once

#include "part/part.h"

#include <vector>

namespace sl {
void registerWarpedLayouts(std::vector<std::unique_ptr<Layout>>& out);

// The LiSPSM view of `receivers` (with `casters` along their light rays) for a camera with view
// matrix `cameraView` with the chosen n; a spot light, or a view (anti)parallel to the light,
// gets the focused map instead, snapped to whole texels when `snap` (layout.snap); the warp fades
// into that map continuously. Cascades call it once per split (z-partitioning and warping).
// The free parameter n: a named endpoint (the survey's slider: z_n PSM-like, n_opt, infinity =
// focused) times a scale.
struct LispsmN {
  enum class Mode { Optimal = 0, ZNear = 1, Infinity = 2 } mode = Mode::Optimal;
  float scale = 1.0f;
};
LispsmN lispsmN(const ParamSet& params);  // from lispsm.n and lispsm.n_scale
std::vector<ParamDecl> lispsmParams();    // their declarations (lispsm and cascaded share them)
// The light view with -z along the light and +y along the view direction projected onto the
// light's plane, turned toward the fixed basis (lightViewMatrix) by 1 - w near the fallback
// (w = 1: fully turned to the view). LiSPSM and LogPSM warp along its +y.
glm::mat4 warpBasis(const Light& light, const glm::vec3& eye, const glm::vec3& viewDir, float cosGamma, float w,
                    float roll);
// How far a warp along the view is turned on, from sin(gamma) between view and light: 0 below
// 0.05 (the view looks along the light: no warp helps), 1 from 0.15, smoothstep between, so n
// (LiSPSM) or δ (LogPSM) and the basis change without a pop when the view turns toward the light.
float viewWarpWeight(float sinGamma);
// The receivers' box in `lightView`, and the light-view z range of receivers and casters (toward
// the light = larger): what a warped view is fitted to.
struct LightViewBox {
  glm::vec3 lo{1e30f}, hi{-1e30f};
  float zMin = 1e30f, zMax = -1e30f;
};
LightViewBox lightViewBox(const glm::mat4& lightView, const std::vector<glm::vec3>& receivers,
                          const std::vector<glm::vec3>& casters);
LightView lispsmView(const Light& light, const glm::mat4& cameraView, const std::vector<glm::vec3>& receivers,
                     const std::vector<glm::vec3>& casters, const LispsmN& n, int size, bool snap,
                     const LayoutJitter& jitter);
}  // namespace sl
