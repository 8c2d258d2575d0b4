// Leaf coverage at a distance (leafCoverage.ts): the sampled alpha scaled up by the mip level
// this fragment reads, so averaged texels of a lobed blade stay above the alpha cutoff.
#ifdef USE_MAP
  {
    vec2 sylvaTexel = vMapUv * vec2(textureSize(map, 0));
    vec2 sylvaDx = dFdx(sylvaTexel);
    vec2 sylvaDy = dFdy(sylvaTexel);
    float sylvaMip = max(0.0, 0.5 * log2(max(dot(sylvaDx, sylvaDx), dot(sylvaDy, sylvaDy))));
    diffuseColor.a *= 1.0 + sylvaMip * uLeafMipAlphaScale;
  }
#endif
