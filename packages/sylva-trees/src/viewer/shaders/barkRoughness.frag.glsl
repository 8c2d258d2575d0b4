float roughnessFactor = roughness;
#ifdef USE_ROUGHNESSMAP
  roughnessFactor *= barkSample(roughnessMap, vRoughnessMapUv).g;
#endif
roughnessFactor = mix(roughnessFactor, 0.6, vBark.y);
