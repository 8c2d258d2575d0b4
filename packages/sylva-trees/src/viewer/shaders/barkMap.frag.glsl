#ifdef USE_MAP
  diffuseColor *= barkSample(map, vMapUv);
#endif
diffuseColor.rgb = mix(diffuseColor.rgb, uBarkYoung, vBark.y) * vBark.z;
