#version 430 core
// Pass 1 of the GPU vertex normals (render/gpu_deformer.cpp): the unnormalised normal (b - a) x (c - a) of every
// triangle (its length is twice the area), from the positions the deformation pass just wrote. Pass 2
// (vertex_normals.comp.glsl) sums them per vertex. Same maths as render/mesh_normals.cpp.

layout(local_size_x = 64) in;

layout(std430, binding = 0) readonly buffer Positions { float positions[]; };  // #V by 3
layout(std430, binding = 1) readonly buffer Triangles { uint triangles[]; };   // #F by 3 (the index buffer)
layout(std430, binding = 2) writeonly buffer FaceNormals { float faceNormals[]; };  // #F by 3

uniform uint uNumFaces;
uniform uint uNumVertices;

vec3 position(uint v) { return vec3(positions[3u * v], positions[3u * v + 1u], positions[3u * v + 2u]); }

void main() {
  // Linear index over a grid that may spill into y (more than 65535 groups).
  const uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
  const uint f = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
  if (f >= uNumFaces) return;
  const uint a = triangles[3u * f], b = triangles[3u * f + 1u], c = triangles[3u * f + 2u];
  vec3 n = vec3(0.0);
  if (a < uNumVertices && b < uNumVertices && c < uNumVertices) {  // as on the CPU: bad faces count for nothing
    const vec3 pa = position(a);
    n = cross(position(b) - pa, position(c) - pa);
  }
  faceNormals[3u * f] = n.x;
  faceNormals[3u * f + 1u] = n.y;
  faceNormals[3u * f + 2u] = n.z;
}
