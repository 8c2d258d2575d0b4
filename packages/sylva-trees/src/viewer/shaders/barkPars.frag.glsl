// Bark look (barkLook.ts): girth-scaled tiling blended between two power-of-two repeats (both
// integers, so the seam at u = 1 still meets u = 0), young bark, occlusion.
uniform vec3 uBarkYoung;
varying vec3 vBark;

vec4 barkSample(sampler2D t, vec2 uv) {
  float level = floor(vBark.x);
  // A short cross-fade: most of a stem shows one scale, not two patterns at once.
  float w = smoothstep(0.3, 0.7, vBark.x - level);
  float n = exp2(level);
  vec2 dx = dFdx(uv);
  vec2 dy = dFdy(uv);
  // One fetch where one scale shows (most of every stem), two only inside the cross-fade.
  if (w <= 0.0) return textureGrad(t, uv * n, dx * n, dy * n);
  if (w >= 1.0) return textureGrad(t, uv * (2.0 * n), dx * (2.0 * n), dy * (2.0 * n));
  vec4 a = textureGrad(t, uv * n, dx * n, dy * n);
  vec4 b = textureGrad(t, uv * (2.0 * n), dx * (2.0 * n), dy * (2.0 * n));
  return mix(a, b, w);
}
