// Impostor bake (impostor.ts): unlit albedo + coverage, object-space normals (n * 0.5 + 0.5) with
// the depth toward the eye in alpha, and the light terms (sun visibility, leaf share): three
// render targets.
layout(location = 0) out highp vec4 outColor;
layout(location = 1) out highp vec4 outNormal;
layout(location = 2) out highp vec4 outLight;
uniform vec3 uColor;
uniform sampler2D uMap;
uniform float uUseMap;
// Bounding radius: the bake camera stands 2 radii from the centre, so depth = (viewZ + 2r) / r.
uniform float uRadius;
// 1 for leaves (their emissive copy and translucency are added when drawn), 0 for bark.
uniform float uLeaf;
// The sun's depth map (tree space → its clip space by uSunMatrix) and its texel size; uUseSun 0
// while that map itself is drawn, or when the bake has no sun.
uniform sampler2D uSunDepth;
uniform mat4 uSunMatrix;
uniform float uSunTexel;
// Offset off the surface (tree units) and depth bias (the sun map's depth units).
uniform float uSunBias;
uniform float uSunDepthBias;
uniform float uUseSun;
// Toward the sun (tree space).
uniform vec3 uSunDir;
varying vec3 vN;
varying vec2 vUv;
varying vec3 vTint;
varying float vViewZ;
varying vec3 vWorld;

// Share of the sun this point receives: 5 × 5 comparisons over about ±6 texels of the sun's
// depth map, as soft as the viewer's shadows (lighting.ts SHADOW_RADIUS on its 1024² map).
float sunVisibility(vec3 n) {
  if (uUseSun < 0.5) return 1.0;
  // Off the surface toward the sun's side of it (a leaf does not shadow itself).
  vec3 off = (dot(n, uSunDir) < 0.0 ? -n : n) * uSunBias;
  vec4 p = uSunMatrix * vec4(vWorld + off, 1.0);
  vec3 s = p.xyz / p.w * 0.5 + 0.5;
  float lit = 0.0;
  for (int y = -2; y <= 2; y++) {
    for (int x = -2; x <= 2; x++) {
      float d = texture2D(uSunDepth, s.xy + vec2(float(x), float(y)) * 3.0 * uSunTexel).r;
      lit += s.z - uSunDepthBias <= d ? 1.0 : 0.0;
    }
  }
  return lit / 25.0;
}

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
  outLight = vec4(sunVisibility(normalize(vN)), uLeaf, 0.0, 1.0);
}
