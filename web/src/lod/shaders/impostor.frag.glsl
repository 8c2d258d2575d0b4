// Impostor (impostor.ts): blends the three views' albedo and normals, lit like the tree.
uniform sampler2D uColor;
uniform sampler2D uNormal;
uniform float uFrames;
uniform float uCellPx;
uniform float uAlphaTest;
uniform float uCoverage;
uniform vec3 uSunDir;
uniform vec3 uSunColor;
uniform vec3 uSky;
uniform vec3 uGround;
#include <common>
#include <fog_pars_fragment>

vec2 atlasUv(vec2 frame, vec2 uv) {
  float e = 0.5 / uCellPx;
  return (frame + clamp(uv, e, 1.0 - e)) / uFrames;
}
float inside(vec2 uv) {
  return step(0.0, uv.x) * step(uv.x, 1.0) * step(0.0, uv.y) * step(uv.y, 1.0);
}
void main() {
  vec2 a0 = atlasUv(vFrame0, vUv0);
  vec2 a1 = atlasUv(vFrame1, vUv1);
  vec2 a2 = atlasUv(vFrame2, vUv2);
  // A sample outside its frame's square is empty.
  vec4 c0 = texture2D(uColor, a0) * inside(vUv0);
  vec4 c1 = texture2D(uColor, a1) * inside(vUv1);
  vec4 c2 = texture2D(uColor, a2) * inside(vUv2);
  // Sharpened blend: one frame dominates away from the frames' borders, so parts far from the
  // tree's centre (the trunk's foot, the crown's top) show less twice.
  vec3 w = vWeights * vWeights * vWeights;
  w /= max(w.x + w.y + w.z, 1e-6);
  vec4 c = c0 * w.x + c1 * w.y + c2 * w.z;
  if (c.a < uAlphaTest) discard;
  vec3 albedo = c.rgb / max(c.a, 1e-3);
  vec4 n0 = texture2D(uNormal, a0);
  vec4 n1 = texture2D(uNormal, a1);
  vec4 n2 = texture2D(uNormal, a2);
  // Normals are premultiplied by coverage (the colour's alpha) in the multisampled bake.
  vec3 nl = (n0.xyz * 2.0 - c0.a) * w.x + (n1.xyz * 2.0 - c1.a) * w.y + (n2.xyz * 2.0 - c2.a) * w.z;
  vec3 n = normalize(mat3(vRotX, vRotY, vRotZ) * nl + vec3(0.0, 1e-4, 0.0));
  vec3 irradiance = mix(uGround, uSky, n.y * 0.5 + 0.5) + uSunColor * max(dot(n, uSunDir), 0.0);
  gl_FragColor = vec4(albedo * irradiance * RECIPROCAL_PI, uCoverage > 0.5 ? c.a : 1.0);
#include <tonemapping_fragment>
#include <colorspace_fragment>
#include <fog_fragment>
}
