// Procedural sky (lighting.ts): zenith-to-horizon gradient, a warm glow around the sun and a
// dark ground below the horizon; linear colours, rendered once into a PMREM environment map.
uniform vec3 uZenith;
uniform vec3 uHorizon;
uniform vec3 uGround;
uniform vec3 uSunDir;
uniform vec3 uSunGlow;
varying vec3 vSkyDir;
void main() {
  vec3 d = normalize(vSkyDir);
  float up = d.y;
  vec3 sky = mix(uHorizon, uZenith, pow(clamp(up, 0.0, 1.0), 0.6));
  float sun = max(dot(d, uSunDir), 0.0);
  sky += uSunGlow * (0.6 * pow(sun, 8.0) + 4.0 * pow(sun, 256.0));
  vec3 ground = mix(uHorizon * 0.6, uGround, clamp(-up * 4.0, 0.0, 1.0));
  gl_FragColor = vec4(up >= 0.0 ? sky : ground, 1.0);
}
