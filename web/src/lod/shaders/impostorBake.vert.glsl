// Impostor bake (impostor.ts): world-space normal, uv and tint of the LOD0 tree, per view.
varying vec3 vN;
varying vec2 vUv;
varying vec3 vTint;
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
  gl_Position = projectionMatrix * viewMatrix * m * vec4(position, 1.0);
}
