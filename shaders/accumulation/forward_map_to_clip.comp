// Forward shadow mapping: the matrices that take a light texel's sample to the eye's clip space
// (accumulation/forward_splat.glsl, MapToClip), once a frame for every splat invocation to read.
#include "accumulation/forward_splat.glsl"
layout(std430) buffer ForwardMapToClipOut { MapToClip forwardMapToClipOut; };  // read as ForwardMapToClip
layout(local_size_x = 1) in;

void main() { forwardMapToClipOut = mapToClip(); }
