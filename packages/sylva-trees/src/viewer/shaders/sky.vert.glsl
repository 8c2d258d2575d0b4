// Procedural sky (lighting.ts): the direction of each point of a sphere around the origin.
varying vec3 vSkyDir;
void main() {
  vSkyDir = normalize(position);
  gl_Position = projectionMatrix * modelViewMatrix * vec4(position, 1.0);
}
