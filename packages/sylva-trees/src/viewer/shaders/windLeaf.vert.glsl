// Leaf displacement, after `#include <begin_vertex>`: flutter in leaf space, then the attachment
// point's branch sway and the main bending in tree space, mapped back to leaf space.
{
  float windS = windEffectiveStrength();
  if (windS > 0.0) {
#ifdef USE_INSTANCING
    vec3 windAnchor = instanceMatrix[3].xyz;
#ifdef WIND_NO_FLUTTER
    // Flowers, fruit and buds (metres, not leaf units): rigid, carried by their anchor only.
    vec3 windLocal = transformed;
#else
    vec3 windLocal = transformed + windLeafFlutter(transformed, normal, windAnchor, windS);
#endif
    vec3 windTree = (instanceMatrix * vec4(windLocal, 1.0)).xyz;
    vec3 windMoved = windMainBend(windTree + windBranchSway(windAnchor, windS), windS);
    transformed = windLocal + inverse(mat3(instanceMatrix)) * (windMoved - windTree);
#else
    transformed = windMainBend(transformed + windBranchSway(transformed, windS), windS);
#endif
  }
}
