#version 330 core
in float vSelected;

uniform vec4 uColor;
uniform vec4 uSelectedColor;

out vec4 fragColor;

void main() {
  vec2 d = gl_PointCoord * 2.0 - 1.0;
  float r2 = dot(d, d);
  if (r2 > 1.0) discard;
  vec4 fill = vSelected > 0.5 ? uSelectedColor : uColor;
  // A dark rim keeps the handles readable over light and dark backgrounds.
  fragColor = r2 > 0.55 ? vec4(0.08, 0.08, 0.1, 1.0) : fill;
}
