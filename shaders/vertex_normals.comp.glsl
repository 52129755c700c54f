#version 430 core
// Pass 2 of the GPU vertex normals (render/gpu_deformer.cpp): each vertex sums the normals of its incident faces
// in a fixed order (a vertex -> face adjacency in CSR form, faces ascending, built once per mesh), then
// normalises. No atomics on floats: the result does not depend on scheduling. Zero for isolated vertices.

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer FaceNormals { float faceNormals[]; };  // #F by 3
layout(std430, binding = 1) readonly buffer AdjacencyOffsets { uint offsets[]; };  // #V + 1
layout(std430, binding = 2) readonly buffer AdjacencyFaces { uint faces[]; };      // offsets[#V]
layout(std430, binding = 3) writeonly buffer Normals { float normals[]; };         // #V by 3 (vertex buffer)

uniform uint uNumVertices;

void main() {
  // Linear index over a grid that may spill into y (more than 65535 groups).
  const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  const uint v = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
  if (v >= uNumVertices) return;
  vec3 sum = vec3(0.0);
  for (uint i = offsets[v]; i < offsets[v + 1u]; ++i) {
    const uint f = faces[i];
    sum += vec3(faceNormals[3u * f], faceNormals[3u * f + 1u], faceNormals[3u * f + 2u]);
  }
  const float len = length(sum);
  const vec3 n = len > 0.0 ? sum / len : vec3(0.0);
  normals[3u * v] = n.x;
  normals[3u * v + 1u] = n.y;
  normals[3u * v + 2u] = n.z;
}
