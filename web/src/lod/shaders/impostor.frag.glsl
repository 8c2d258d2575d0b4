// Impostor (impostor.ts): casts the fragment's eye ray into each of the three views, finds where
// it meets that view's surface (its baked depth), and blends the three views' albedo and normals
// found there, lit like the tree: sky, sun (times the share of it the bake saw reach each texel)
// and, on leaves, the leaf material's emissive copy and light through the blade (Foliage.ts,
// lighting.ts).
uniform sampler2D uColor;
uniform sampler2D uNormal;
uniform sampler2D uLight;
uniform float uLeafEmissive;
uniform float uLeafTranslucency;
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

// The most march steps per view (hemiOct.ts `parallaxSteps`).
#define MAX_STEPS 32

vec3 hemiOctDecode(vec2 uv) {
  vec2 a = uv * 2.0 - 1.0;
  vec2 p = vec2(a.x + a.y, a.x - a.y) * 0.5;
  float y = max(1.0 - abs(p.x) - abs(p.y), 0.0);
  return normalize(vec3(p.x, y, p.y));
}
vec2 atlasUv(vec2 frame, vec2 uv) {
  float e = 0.5 / uCellPx;
  return (frame + clamp(uv, e, 1.0 - e)) / uFrames;
}
float inside(vec2 uv) {
  return step(0.0, uv.x) * step(uv.x, 1.0) * step(0.0, uv.y) * step(uv.y, 1.0);
}
// The view's surface depth at uv (radii toward the eye), or -2 (behind everything) where empty.
float surfaceDepth(vec2 frame, vec2 uv) {
  vec2 a = atlasUv(frame, uv);
  float coverage = textureLod(uColor, a, 0.0).a * inside(uv);
  if (coverage < 0.5) return -2.0;
  return textureLod(uNormal, a, 0.0).a / coverage * 2.0 - 1.0;
}
// Where the ray eye + t·w meets the surface of view `frame` (hemiOct.ts `frameRay`,
// `parallaxHit`): its image-plane point uv0 moves by s·h at depth h. March h from the front of the
// bounding sphere back; at the first step behind the surface, bisect to where the ray enters it. A
// ray that enters more than THICKNESS behind the surface passes behind it (no wall behind a
// trunk's silhouette) and marches on. A miss is empty (outside the frame).
#define THICKNESS 0.03
vec2 frameHit(vec2 frame, vec3 eye, vec3 w) {
  vec3 d = hemiOctDecode(frame / (uFrames - 1.0));
  vec3 rr = vec3(d.z, 0.0, -d.x);
  vec3 r = length(rr) < 1e-6 ? vec3(1.0, 0.0, 0.0) : normalize(rr);
  vec3 u = cross(d, r);
  float den = min(dot(w, d), -1e-4);
  vec3 p0 = eye - w * (dot(eye, d) / den);
  vec2 uv0 = vec2(dot(p0, r), dot(p0, u)) * 0.5 + 0.5;
  vec2 s = vec2(dot(w, r), dot(w, u)) * (0.5 / den);
  int n = int(clamp(ceil(length(s) * 2.0 * uCellPx / 2.0), 2.0, float(MAX_STEPS)));
  float dh = 2.0 / float(n);
  float hPrev = 1.0;
  float fPrev = surfaceDepth(frame, uv0 + s) - 1.0;
  for (int k = 1; k <= MAX_STEPS; k++) {
    if (k > n) break;
    float h = 1.0 - dh * float(k);
    float f = surfaceDepth(frame, uv0 + s * h) - h;
    if (f >= 0.0 && fPrev < 0.0) {
      float front = hPrev;
      float back = h;
      float fb = f;
      for (int b = 0; b < 4; b++) {
        float mid = 0.5 * (front + back);
        float fm = surfaceDepth(frame, uv0 + s * mid) - mid;
        if (fm >= 0.0) {
          back = mid;
          fb = fm;
        } else {
          front = mid;
        }
      }
      if (fb <= THICKNESS) return uv0 + s * back;
    } else if (f >= 0.0 && f <= THICKNESS) {
      return uv0 + s * h;
    }
    hPrev = h;
    fPrev = f;
  }
  return vec2(-1.0);
}
void main() {
  vec3 w = vLocal - vEye;
  // Sharpened blend: one view dominates away from the frames' borders.
  vec3 wt = vWeights * vWeights * vWeights;
  wt /= max(wt.x + wt.y + wt.z, 1e-6);
  // A view with (almost) no weight is not marched.
  vec2 h0 = wt.x > 1e-3 ? frameHit(vFrame0, vEye, w) : vec2(-1.0);
  vec2 h1 = wt.y > 1e-3 ? frameHit(vFrame1, vEye, w) : vec2(-1.0);
  vec2 h2 = wt.z > 1e-3 ? frameHit(vFrame2, vEye, w) : vec2(-1.0);
  vec2 a0 = atlasUv(vFrame0, h0);
  vec2 a1 = atlasUv(vFrame1, h1);
  vec2 a2 = atlasUv(vFrame2, h2);
  // A sample outside its frame's square is empty.
  vec4 c0 = textureLod(uColor, a0, 0.0) * inside(h0);
  vec4 c1 = textureLod(uColor, a1, 0.0) * inside(h1);
  vec4 c2 = textureLod(uColor, a2, 0.0) * inside(h2);
  vec4 c = c0 * wt.x + c1 * wt.y + c2 * wt.z;
  if (c.a < uAlphaTest) discard;
  vec3 albedo = c.rgb / max(c.a, 1e-3);
  vec3 n0 = textureLod(uNormal, a0, 0.0).xyz;
  vec3 n1 = textureLod(uNormal, a1, 0.0).xyz;
  vec3 n2 = textureLod(uNormal, a2, 0.0).xyz;
  // Normals are premultiplied by coverage (the colour's alpha) in the multisampled bake.
  vec3 nl = (n0 * 2.0 - c0.a) * wt.x + (n1 * 2.0 - c1.a) * wt.y + (n2 * 2.0 - c2.a) * wt.z;
  mat3 rot = mat3(vRotX, vRotY, vRotZ);
  vec3 n = normalize(rot * nl + vec3(0.0, 1e-4, 0.0));
  // Light terms, premultiplied by coverage: the sun's share and the leaves' share.
  vec4 l = textureLod(uLight, a0, 0.0) * inside(h0) * wt.x
    + textureLod(uLight, a1, 0.0) * inside(h1) * wt.y
    + textureLod(uLight, a2, 0.0) * inside(h2) * wt.z;
  float sunShare = clamp(l.r / max(c.a, 1e-3), 0.0, 1.0);
  float leaf = clamp(l.g / max(c.a, 1e-3), 0.0, 1.0);
  vec3 irradiance = mix(uGround, uSky, n.y * 0.5 + 0.5)
    + uSunColor * max(dot(n, uSunDir), 0.0) * sunShare;
  // Leaves: the dim emissive copy, and sunlight through the blade when the sun is behind it,
  // strongest looking toward the sun (leafTranslucency.frag.glsl).
  float back = max(-dot(n, uSunDir), 0.0);
  float forward = pow(max(dot(normalize(rot * w), uSunDir), 0.0), 3.0);
  vec3 through = uSunColor * uLeafTranslucency * back * (0.35 + 0.65 * forward);
  vec3 lit = albedo * (irradiance * RECIPROCAL_PI + leaf * (uLeafEmissive + through));
  // With coverage: up close, where a texel spans several pixels, the filtered coverage ramps over
  // that many pixels and the sky showed through a wide rim (10% brighter than LOD0 at a screen
  // size of 0.9); the ramp is narrowed to about one pixel about the alpha test. Far off
  // (a texel under a pixel) the coverage blends as baked.
  float texelsPerPixel = length(fwidth(a0 * uFrames * uCellPx));
  float sharpen = max(1.0, 1.0 / max(texelsPerPixel, 1e-3));
  float alpha = clamp((c.a - uAlphaTest) * sharpen + uAlphaTest, 0.0, 1.0);
  gl_FragColor = vec4(lit, uCoverage > 0.5 ? alpha : 1.0);
#include <tonemapping_fragment>
#include <colorspace_fragment>
#include <fog_fragment>
}
