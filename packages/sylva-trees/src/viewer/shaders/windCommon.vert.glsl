// Uniforms and functions shared by every wind shader (mirrors `wind.math.ts`).
uniform float uWindTime;
uniform vec2 uWindDirection;
uniform float uWindStrength;
uniform vec2 uWindGust;
uniform float uWindEnabled;
uniform vec4 uWindTree;
float windSmoothCurve(float x) { return x * x * (3.0 - 2.0 * x); }
float windTriangleWave(float x) { return abs(fract(x + 0.5) * 2.0 - 1.0); }
float windSmoothTriangleWave(float x) { return windSmoothCurve(windTriangleWave(x)); }
float windWave2(float a, float b) { return windSmoothTriangleWave(a) + windSmoothTriangleWave(b) - 1.0; }
float windHash(vec3 p3) {
  p3 = fract(p3 * 0.1031);
  p3 += dot(p3, p3.zyx + 31.32);
  return fract((p3.x + p3.y) * p3.z);
}
float windGustEnvelope(float t, float freq) {
  float s = 0.5 + 0.5 * (0.6 * sin(6.2831853 * freq * t) + 0.4 * sin(6.2831853 * freq * 2.31 * t + 1.3));
  return s * s;
}
float windEffectiveStrength() {
  if (uWindEnabled < 0.5) return 0.0;
  return uWindStrength * (1.0 + uWindGust.x * windGustEnvelope(uWindTime, uWindGust.y));
}
vec3 windMainBend(vec3 p, float s) {
  float h = max(uWindTree.x, 0.1);
  float t = uWindTime;
  float sway = 1.0 + 0.4 * windWave2(t * 0.23, t * 0.137 + 0.3);
  float amount = s * sway * WIND_MAIN_BEND * h;
  float y = max(p.y, 0.0);
  float bf = y / h + 1.0;
  bf = bf * bf - bf;
  vec3 q = p;
  q.xz += uWindDirection * amount * bf;
  float len = length(p);
  float qLen = length(q);
  if (len < 1e-6 || qLen < 1e-6) return p;
  return q * (len / qLen);
}
vec3 windBranchSway(vec3 p, float s) {
  float h = max(uWindTree.x, 0.1);
  float r = max(uWindTree.y, 0.1);
  float t = uWindTime;
  float flex = clamp(length(p.xz) / r, 0.0, 1.0);
  flex *= flex * clamp(p.y / (0.25 * h), 0.0, 1.0);
  float phase = -dot(p.xz, uWindDirection) * 0.12 + dot(p, vec3(0.19, 0.07, 0.23));
  float sway = windWave2(t * 0.375 + phase, t * 0.193 + phase * 1.37);
  float bob = windWave2(t * 0.61 + phase * 1.7 + 0.25, t * 0.29 + phase * 0.83 + 0.5);
  float amp = s * flex * WIND_BRANCH_SWAY * h;
  return vec3(uWindDirection.x * sway, 0.5 * bob, uWindDirection.y * sway) * amp;
}
