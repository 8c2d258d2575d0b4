// Impostor bake (impostor.ts): world-space position and normal, uv and tint of the LOD0 tree, and
// the view-space depth, per view.
varying vec3 vN;
varying vec2 vUv;
varying vec3 vTint;
varying float vViewZ;
varying vec3 vWorld;
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
  vec4 world = m * vec4(position, 1.0);
  vWorld = world.xyz;
  vec4 view = viewMatrix * world;
  vViewZ = view.z;
  gl_Position = projectionMatrix * view;
}
