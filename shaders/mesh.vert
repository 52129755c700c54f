#version 330 core
// Deformed mesh: positions and smooth normals are uploaded every frame (render/mesh_renderer.cpp).
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aScalar;  // colour-map coordinate (mesh_renderer.h: setScalars)

uniform mat4 uView;
uniform mat4 uProjection;

out vec3 vPositionView;
out vec3 vNormalView;
out float vScalar;

void main() {
  vec4 p = uView * vec4(aPosition, 1.0);
  vPositionView = p.xyz;
  vNormalView = mat3(uView) * aNormal;  // the view matrix is a rigid motion
  vScalar = aScalar;
  gl_Position = uProjection * p;
}
