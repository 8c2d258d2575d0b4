// Impostor (impostor.ts): a camera-facing quad that picks the three nearest baked views of the
// hemi-octahedral grid and their blend weights; the fragment shader casts the rays.
uniform vec3 uCentre;
uniform float uRadius;
uniform float uFrames;
#include <common>
#include <fog_pars_vertex>

vec2 hemiOctEncode(vec3 d) {
  d.y = max(d.y, 0.0);
  float s = max(abs(d.x) + d.y + abs(d.z), 1e-6);
  vec2 p = d.xz / s;
  return vec2(p.x + p.y, p.x - p.y) * 0.5 + 0.5;
}

void main() {
  mat4 m = modelMatrix;
#ifdef USE_INSTANCING
  m = m * instanceMatrix;
#endif
  float scale = length(m[0].xyz);
  mat3 rot = mat3(m[0].xyz / scale, m[1].xyz / scale, m[2].xyz / scale);
  vec3 centreW = (m * vec4(uCentre, 1.0)).xyz;
  vec3 eyeL = transpose(rot) * (cameraPosition - centreW) / scale;
  vec3 toEye = normalize(eyeL);
  vec3 view = normalize(vec3(toEye.x, max(toEye.y, 0.0) + 1e-4, toEye.z));
  vec3 rr = vec3(view.z, 0.0, -view.x);
  vec3 r = length(rr) < 1e-6 ? vec3(1.0, 0.0, 0.0) : normalize(rr);
  vec3 u = cross(view, r);
  // 5 % margin: the sphere's perspective outline is a little larger than its radius.
  vec3 local = (r * position.x + u * position.y) * 2.1 * uRadius;
  vec4 mvPosition = viewMatrix * (m * vec4(uCentre + local, 1.0));
  gl_Position = projectionMatrix * mvPosition;

  vec2 g = hemiOctEncode(view) * (uFrames - 1.0);
  vec2 c = min(floor(g), vec2(uFrames - 2.0));
  vec2 f = g - c;
  if (f.x + f.y <= 1.0) {
    vFrame0 = c; vFrame1 = c + vec2(1.0, 0.0); vFrame2 = c + vec2(0.0, 1.0);
    vWeights = vec3(1.0 - f.x - f.y, f.x, f.y);
  } else {
    vFrame0 = c + 1.0; vFrame1 = c + vec2(0.0, 1.0); vFrame2 = c + vec2(1.0, 0.0);
    vWeights = vec3(f.x + f.y - 1.0, 1.0 - f.x, 1.0 - f.y);
  }
  vEye = eyeL / uRadius;
  vLocal = local / uRadius;
  vRotX = rot[0]; vRotY = rot[1]; vRotZ = rot[2];
#include <fog_vertex>
}
