#version 330 core
// Cage vertex handles: round point sprites drawn without depth test, so they stay visible through the mesh.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in float aSelected;

uniform mat4 uView;
uniform mat4 uProjection;
uniform float uPointSize;

out float vSelected;

void main() {
  gl_Position = uProjection * (uView * vec4(aPosition, 1.0));
  gl_PointSize = aSelected > 0.5 ? uPointSize * 1.25 : uPointSize;
  vSelected = aSelected;
}
