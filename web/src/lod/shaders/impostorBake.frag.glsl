// Impostor bake (impostor.ts): unlit albedo + coverage and object-space normals (n * 0.5 + 0.5),
// two render targets.
layout(location = 0) out highp vec4 outColor;
layout(location = 1) out highp vec4 outNormal;
uniform vec3 uColor;
uniform sampler2D uMap;
uniform float uUseMap;
varying vec3 vN;
varying vec2 vUv;
varying vec3 vTint;
void main() {
  vec4 albedo = vec4(uColor * vTint, 1.0);
  if (uUseMap > 0.5) {
    vec4 t = texture2D(uMap, vUv);
    if (t.a < 0.5) discard;
    albedo.rgb *= t.rgb;
  }
  vec3 n = normalize(vN) * (gl_FrontFacing ? 1.0 : -1.0);
  outColor = vec4(albedo.rgb, 1.0);
  outNormal = vec4(n * 0.5 + 0.5, 1.0);
}
