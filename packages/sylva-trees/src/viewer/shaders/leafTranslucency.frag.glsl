// Leaf translucency (lighting.ts): sunlight through the blade when the sun is behind the leaf,
// strongest when looking toward the sun; the leaf's tint (crown depth included) colours it.
#if NUM_DIR_LIGHTS > 0
{
  vec3 leafL = directionalLights[ 0 ].direction;
  float leafBack = saturate( -dot( normal, leafL ) );
  float leafForward = pow( saturate( dot( -geometryViewDir, leafL ) ), 3.0 );
  reflectedLight.directDiffuse += diffuseColor.rgb * directionalLights[ 0 ].color
    * uLeafTranslucency * leafBack * ( 0.35 + 0.65 * leafForward );
}
#endif
