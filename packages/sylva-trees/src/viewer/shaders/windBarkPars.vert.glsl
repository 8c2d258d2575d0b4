// Per-vertex attributes and twig bending of the bark.
attribute vec4 windPivot;
attribute vec4 windParams;
vec3 windTwigBend(vec3 p, vec4 pivot, vec4 params, float s) {
  float t = uWindTime;
  vec3 r = p - pivot.xyz;
  float along = length(r);
  if (along < 1e-6) return vec3(0.0);
  float level = clamp(pivot.w / 3.0, 0.0, 1.0);
  float bend = 1.0 - clamp(params.y, 0.0, 1.0);
  float gain = bend * bend * bend * bend * level * level;
  float phase = params.x + windHash(pivot.xyz);
  float w = windWave2(t * 0.793 + phase, t * 0.375 + phase * 1.3);
  float angle = s * WIND_TWIG_ANGLE * gain * w;
  vec3 wv = normalize(vec3(uWindDirection.x, 0.35, uWindDirection.y));
  vec3 rn = r / along;
  return (wv - rn * dot(rn, wv)) * (angle * along);
}
