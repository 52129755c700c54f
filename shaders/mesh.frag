#version 330 core
// Two-sided headlight shading: the normal is flipped towards the eye, so meshes whose faces point inward
// (or open surfaces seen from behind) shade the same as outward-facing ones.
in vec3 vPositionView;
in vec3 vNormalView;
in float vScalar;

uniform vec3 uColor;
uniform bool uOrthographic;
uniform bool uMapped;          // colour from the scalar through the colour map instead of uColor
uniform float uMapRow;         // texture row of the map (0.25 diverging, 0.75 viridis)
uniform vec3 uFoldoverColor;   // scalar -1
uniform sampler2D uColorMaps;
uniform bool uFlat;  // facet normals from screen-space derivatives instead of the smooth vertex normals

out vec4 fragColor;

void main() {
  vec3 toEye = uOrthographic ? vec3(0.0, 0.0, 1.0) : normalize(-vPositionView);
  vec3 n = uFlat ? cross(dFdx(vPositionView), dFdy(vPositionView)) : vNormalView;
  float len = length(n);
  n = len > 1e-12 ? n / len : toEye;
  if (dot(n, toEye) < 0.0) n = -n;

  // Key light slightly above-left of the eye, a dim fill from the other side, and ambient.
  vec3 key = normalize(vec3(-0.35, 0.45, 1.0));
  vec3 fill = normalize(vec3(0.6, -0.2, 0.5));
  float diffuse = 0.70 * max(dot(n, key), 0.0) + 0.20 * max(dot(n, fill), 0.0);
  vec3 h = normalize(key + toEye);
  float specular = 0.25 * pow(max(dot(n, h), 0.0), 48.0);
  vec3 color = uColor * (0.22 + diffuse) + vec3(specular);
  if (uMapped) {  // lighter shading and no highlight, so the map's colours read true
    vec3 base = vScalar < -1.5 ? vec3(0.5) : vScalar < -0.5 ? uFoldoverColor : texture(uColorMaps, vec2(vScalar, uMapRow)).rgb;
    color = base * (0.55 + 0.5 * diffuse);
  }
  fragColor = vec4(pow(clamp(color, 0.0, 1.0), vec3(1.0 / 1.1)), 1.0);
}
