// Impostor bake (impostor.ts): world-space normal, uv and tint of the LOD0 tree, and the view-space
// depth, per view.
varying vec3 vN;
varying vec2 vUv;
varying vec3 vTint;
varying float vViewZ;
void main() {
  mat4 m = modelMatrix;
#ifdef USE_INSTANCING
  m = modelMatrix * instanceMatrix;
#endif
  vN = normalize(transpose(inverse(mat3(m))) * normal);
  vUv = uv;
  vTint = vec3(1.0);
#ifdef USE_INSTANCING_COLOR
  vTint = instanceColor;
#endif
#ifdef USE_COLOR
  vTint *= color;
#endif
  vec4 view = viewMatrix * m * vec4(position, 1.0);
  vViewZ = view.z;
  gl_Position = projectionMatrix * view;
}
