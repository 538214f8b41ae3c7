// Where the shadow passes' caster depth comes from. A layout whose stored depth is affine in the
// world position (SL_LAYOUT_DEPTH_AFFINE: light-view linear depth) has it computed per vertex
// and interpolated: perspective-correct interpolation reproduces an affine function of the
// position exactly, as it does the position itself. Per fragment it was three interpolated
// coordinates and a row of the view matrix: half of face partitioning's shadow pass on llvmpipe
// (43 -> 25 ms at 1280x720), where perspective maps write every fragment's depth. Not under a
// warp (SL_LOG_WARP: the depth of a tessellated chord is solved per fragment) nor where a
// tessellation stage sits between (the paraboloid's depth is radial: its module does not define
// SL_LAYOUT_DEPTH_AFFINE).
#ifndef SL_CASTER_DEPTH_GLSL
#define SL_CASTER_DEPTH_GLSL
#if defined(SL_LAYOUT_DEPTH_AFFINE) && !defined(SL_LOG_WARP)
#define SL_CASTER_DEPTH_VARYING
#endif
#endif
