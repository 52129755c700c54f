#version 330 core
// Cage faces and edges: one colour per draw call.
layout(location = 0) in vec3 aPosition;

uniform mat4 uView;
uniform mat4 uProjection;
uniform float uDepthOffset;  // pulls edges slightly towards the eye so they win over coplanar faces

void main() {
  vec4 clip = uProjection * (uView * vec4(aPosition, 1.0));
  clip.z -= uDepthOffset * clip.w;
  gl_Position = clip;
}
