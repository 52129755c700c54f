#version 430 core
// The exterior blend of core/deform/frame_evaluation.h on the GPU (render/gpu_deformer.cpp), after
// deform_frame.comp.glsl has written every exterior point's proxy and anchor rows to Extra:
//
//   position_p += w (extra_{2e} - extra_{2e+1})        i.e.  x~ = S(x) + w(d) [phi(x_in) - S(x_in)]
//
// One invocation per exterior point e; points are distinct, so no two invocations write the same position.

layout(local_size_x = 64) in;

struct Blend {
  uint point;
  float weight;
};
layout(std430, binding = 0) readonly buffer Blends { Blend blends[]; };
// 2 #E by 3 floats: row 2e the proxy phi(x_in), row 2e + 1 the anchor S(x_in).
layout(std430, binding = 1) readonly buffer Extra { float extra[]; };
// The mesh renderer's vertex buffer: #P by 3 floats.
layout(std430, binding = 2) buffer Positions { float positions[]; };

uniform uint uNumBlends;

void main() {
  const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  const uint e = group * 64u + gl_LocalInvocationID.x;
  if (e >= uNumBlends) return;
  const Blend blend = blends[e];
  for (uint a = 0u; a < 3u; ++a)
    positions[3u * blend.point + a] += blend.weight * (extra[6u * e + a] - extra[6u * e + 3u + a]);
}
