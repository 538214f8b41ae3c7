// The paraboloid (stereographic) image of a unit direction d in a hemisphere view's frame (its
// axis is -z): d.xy / (1 - d.z), the hemisphere filling the unit disk, scaled by
// 1 / kParaboloidWindow so that filter taps just past the rim read drawn texels. Shared by the
// dual-paraboloid layout (layouts/dual_paraboloid.glsl) and the reduction that fits its windows
// to the visible pixels (passes/point_face_bounds.comp); app/part/light_space.h,
// paraboloidDiskImage, is the same on the CPU.
const float kParaboloidWindow = 1.05;  // app/part/light_space.h, kParaboloidWindow

// 1 - d.z is 0 only at the opposite pole, whose image is at infinity; clamped there (such a
// point is behind the hemisphere: the shadow pass culls it, the lookup reads the other view).
vec2 paraboloidDiskImage(vec3 d) { return d.xy / max(1.0 - d.z, 1e-4) / kParaboloidWindow; }
