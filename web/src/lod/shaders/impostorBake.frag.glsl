// Impostor bake (impostor.ts): unlit albedo + coverage, and object-space normals (n * 0.5 + 0.5)
// with the depth toward the eye in alpha, two render targets.
layout(location = 0) out highp vec4 outColor;
layout(location = 1) out highp vec4 outNormal;
uniform vec3 uColor;
uniform sampler2D uMap;
uniform float uUseMap;
// Bounding radius: the bake camera stands 2 radii from the centre, so depth = (viewZ + 2r) / r.
uniform float uRadius;
varying vec3 vN;
varying vec2 vUv;
varying vec3 vTint;
varying float vViewZ;
void main() {
  vec4 albedo = vec4(uColor * vTint, 1.0);
  if (uUseMap > 0.5) {
    vec4 t = texture2D(uMap, vUv);
    if (t.a < 0.5) discard;
    albedo.rgb *= t.rgb;
  }
  vec3 n = normalize(vN) * (gl_FrontFacing ? 1.0 : -1.0);
  float depth = clamp((vViewZ + 2.0 * uRadius) / uRadius * 0.5 + 0.5, 0.0, 1.0);
  outColor = vec4(albedo.rgb, 1.0);
  outNormal = vec4(n * 0.5 + 0.5, depth);
}
