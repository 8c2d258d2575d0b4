// Leaf flutter (leaf units, along the blade's normal).
vec3 windLeafFlutter(vec3 local, vec3 nrm, vec3 anchor, float s) {
  float t = uWindTime;
  float ph = windHash(anchor * 7.31);
  float vtx = local.x * 0.37 + local.y * 0.71;
  float w = windWave2(t * 1.975 + ph + vtx, t * 0.793 + ph * 1.7 + vtx);
  float edge = max(local.y, 0.0) + abs(local.x);
  return nrm * (w * edge * WIND_LEAF_FLUTTER * min(s, 1.5));
}
