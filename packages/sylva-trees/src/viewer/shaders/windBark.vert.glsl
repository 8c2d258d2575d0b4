// Bark displacement, after `#include <begin_vertex>` (object space = tree space).
{
  float windS = windEffectiveStrength();
  if (windS > 0.0) {
    vec3 windP = transformed;
    vec3 windQ = windP + windBranchSway(windP, windS);
    // Only with the core's data: a mesh drawn with this material but without the attributes
    // (LOD levels) reads constant defaults, whose distance from the root is 0.
    if (uWindTree.z > 0.5 && windParams.z > 0.0) {
      windQ += windTwigBend(windP, windPivot, windParams, windS);
    }
    transformed = windMainBend(windQ, windS);
  }
}
