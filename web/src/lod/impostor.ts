/**
 * Octahedral impostors (ANCHORS §6), baked in the browser:
 *
 * * **Bake**: the LOD0 tree is rendered from the `n × n` view directions of a hemi-octahedral
 *   grid (`hemiOct.ts`) with an orthographic camera fitted to its bounding sphere, one frame per
 *   atlas cell, into one multisampled render target with two colour attachments (one draw per
 *   frame): albedo + coverage (unlit, premultiplied) and object-space normals (`n · 0.5 + 0.5`,
 *   leaves' back faces flipped toward the camera, premultiplied by coverage).
 * * **Draw**: a camera-facing quad (per instance in the forest) whose vertex shader finds the
 *   3 frames around the view direction in the tree's own frame and their barycentric weights,
 *   and projects the quad's corners onto each frame's image plane along the eye ray; the fragment
 *   shader blends the 3 samples, alpha-tests, and relights with the blended normal (hemisphere
 *   light + sun, the viewer's lights), so the impostor follows the scene's lighting.
 */
import type { Vector3 } from 'three';
import {
  Color,
  DoubleSide,
  FrontSide,
  GLSL3,
  InstancedMesh,
  LinearFilter,
  Mesh,
  OrthographicCamera,
  PlaneGeometry,
  RGBAFormat,
  Scene,
  ShaderMaterial,
  UniformsLib,
  UniformsUtils,
  UnsignedByteType,
  Vector4,
  WebGLRenderTarget,
  type BufferGeometry,
  type Sphere,
  type Texture,
  type WebGLRenderer,
} from 'three';
import { impostorLights, type ImpostorLights } from '../viewer/lighting';
import { frameDirection, viewBasis } from './hemiOct';
import { wrapInstances } from '../viewer/instances';

/** One part of the tree to bake: its geometry (instanced or not), base colour and texture. */
export interface BakePart {
  geometry: BufferGeometry;
  /** Instance matrices (16 floats each) for an instanced part (the leaves). */
  instances?: { matrices: Float32Array; colors?: Float32Array } | undefined;
  /** Base colour (CSS). */
  color: string;
  /** Colour texture with alpha (leaves), or null. */
  map: Texture | null;
  /** Vertex colours present (the merged leaves of the forest). */
  vertexColors?: boolean;
  /** Leaves: two-sided, alpha-tested. */
  doubleSided?: boolean;
}

/** Bake settings. */
export interface BakeOptions {
  /** Frames per side of the atlas (default 8: 64 views). */
  frames?: number;
  /** Pixels per frame side (default 128). */
  cellPx?: number;
  /**
   * Multisampled bake (default 4 samples): a texel's alpha is the share of it the tree covers,
   * so leaves and twigs thinner than a texel stay partly transparent, as LOD0 draws them.
   */
  samples?: number;
}

/** Impostor drawing options. */
export interface ImpostorDrawOptions {
  /**
   * Partial coverage (default false): texels blend with what is behind them by the share of them
   * the tree covers, as LOD0's sub-pixel twigs and leaves do on an antialiased canvas (the
   * viewer's single impostor). Off, the alpha test alone decides (the forest's instanced
   * impostors, drawn without sorting).
   */
  coverage?: boolean;
}

/** A baked impostor. */
export interface ImpostorAtlas {
  color: Texture;
  normal: Texture;
  frames: number;
  cellPx: number;
  /** Bounding sphere the frames were fitted to (tree space). */
  centre: Vector3;
  radius: number;
  /** Milliseconds spent baking (CPU time of the render calls). */
  bakeMs: number;
  dispose(): void;
}

const BAKE_VERTEX = /* glsl */ `
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
}`;

const BAKE_FRAGMENT = /* glsl */ `
layout(location = 0) out highp vec4 outColor;
layout(location = 1) out highp vec4 outNormal;
uniform vec3 uColor;
uniform sampler2D uMap;
uniform float uUseMap;
varying vec3 vN;
varying vec2 vUv;
varying vec3 vTint;
void main() {
  vec4 albedo = vec4(uColor * vTint, 1.0);
  if (uUseMap > 0.5) {
    vec4 t = texture2D(uMap, vUv);
    if (t.a < 0.5) discard;
    albedo.rgb *= t.rgb;
  }
  vec3 n = normalize(vN) * (gl_FrontFacing ? 1.0 : -1.0);
  outColor = vec4(albedo.rgb, 1.0);
  outNormal = vec4(n * 0.5 + 0.5, 1.0);
}`;

function bakeMaterial(part: BakePart): ShaderMaterial {
  return new ShaderMaterial({
    vertexShader: BAKE_VERTEX,
    fragmentShader: BAKE_FRAGMENT,
    uniforms: {
      uColor: { value: new Color(part.color) },
      uMap: { value: part.map },
      uUseMap: { value: part.map ? 1 : 0 },
    },
    glslVersion: GLSL3,
    vertexColors: part.vertexColors ?? false,
    side: part.doubleSided ? DoubleSide : FrontSide,
  });
}

/**
 * Renders `parts` from the `frames × frames` hemi-octahedral views fitted to `sphere` into a
 * colour and a normal atlas. Restores the renderer's target, viewport and clear state.
 */
export function bakeImpostor(
  renderer: WebGLRenderer,
  parts: BakePart[],
  sphere: Sphere,
  options: BakeOptions = {},
): ImpostorAtlas {
  const t0 = performance.now();
  const frames = options.frames ?? 8;
  const cellPx = options.cellPx ?? 128;
  const size = frames * cellPx;
  const scene = new Scene();
  const materials: ShaderMaterial[] = [];
  const meshes: Mesh[] = [];
  for (const part of parts) {
    const material = bakeMaterial(part);
    materials.push(material);
    let mesh: Mesh;
    if (part.instances) {
      mesh = wrapInstances(part.geometry, material, part.instances.matrices, part.instances.colors);
    } else {
      mesh = new Mesh(part.geometry, material);
    }
    mesh.frustumCulled = false;
    meshes.push(mesh);
    scene.add(mesh);
  }
  // One target with two colour attachments (albedo, normal): each frame is drawn once.
  const target = new WebGLRenderTarget(size, size, {
    count: 2,
    format: RGBAFormat,
    type: UnsignedByteType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    generateMipmaps: false,
    depthBuffer: true,
    samples: options.samples ?? 4,
  });
  const r = Math.max(sphere.radius, 1e-3);
  const camera = new OrthographicCamera(-r, r, r, -r, r * 0.25, r * 3.75);
  const previousTarget = renderer.getRenderTarget();
  const previousClear = new Color();
  renderer.getClearColor(previousClear);
  const previousAlpha = renderer.getClearAlpha();
  const previousAutoClear = renderer.autoClear;
  const previousShadows = renderer.shadowMap.autoUpdate;
  renderer.shadowMap.autoUpdate = false;
  renderer.setClearColor(0x000000, 0);
  renderer.autoClear = false;
  try {
    target.scissorTest = false;
    target.viewport.set(0, 0, size, size);
    renderer.setRenderTarget(target);
    renderer.clear(true, true, true);
    target.scissorTest = true;
    for (let i = 0; i < frames; i++) {
      for (let j = 0; j < frames; j++) {
        const d = frameDirection(i, j, frames);
        const { up } = viewBasis(d);
        camera.position.set(
          sphere.center.x + d[0] * 2 * r,
          sphere.center.y + d[1] * 2 * r,
          sphere.center.z + d[2] * 2 * r,
        );
        camera.up.set(up[0], up[1], up[2]);
        camera.lookAt(sphere.center);
        camera.updateMatrixWorld();
        const cell = new Vector4(i * cellPx, j * cellPx, cellPx, cellPx);
        target.viewport.copy(cell);
        target.scissor.copy(cell);
        renderer.setRenderTarget(target);
        // Colour too: a multisampled target's samples may be discarded after each resolve.
        renderer.clear(true, true, false);
        renderer.render(scene, camera);
      }
    }
    target.scissorTest = false;
  } finally {
    renderer.setRenderTarget(previousTarget);
    renderer.setClearColor(previousClear, previousAlpha);
    renderer.autoClear = previousAutoClear;
    renderer.shadowMap.autoUpdate = previousShadows;
    for (const m of materials) m.dispose();
    for (const mesh of meshes) if (mesh instanceof InstancedMesh) mesh.dispose();
  }
  return {
    color: target.textures[0]!,
    normal: target.textures[1]!,
    frames,
    cellPx,
    centre: sphere.center.clone(),
    radius: r,
    bakeMs: performance.now() - t0,
    dispose: () => target.dispose(),
  };
}

const IMPOSTOR_VERTEX = /* glsl */ `
uniform vec3 uCentre;
uniform float uRadius;
uniform float uFrames;
varying vec2 vUv0;
varying vec2 vUv1;
varying vec2 vUv2;
varying vec2 vFrame0;
varying vec2 vFrame1;
varying vec2 vFrame2;
varying vec3 vWeights;
varying vec3 vRotX;
varying vec3 vRotY;
varying vec3 vRotZ;
#include <common>
#include <fog_pars_vertex>

vec2 hemiOctEncode(vec3 d) {
  d.y = max(d.y, 0.0);
  float s = max(abs(d.x) + d.y + abs(d.z), 1e-6);
  vec2 p = d.xz / s;
  return vec2(p.x + p.y, p.x - p.y) * 0.5 + 0.5;
}
vec3 hemiOctDecode(vec2 uv) {
  vec2 a = uv * 2.0 - 1.0;
  vec2 p = vec2(a.x + a.y, a.x - a.y) * 0.5;
  float y = max(1.0 - abs(p.x) - abs(p.y), 0.0);
  return normalize(vec3(p.x, y, p.y));
}
void viewBasis(vec3 d, out vec3 r, out vec3 u) {
  vec3 rr = vec3(d.z, 0.0, -d.x);
  float l = length(rr);
  r = l < 1e-6 ? vec3(1.0, 0.0, 0.0) : rr / l;
  u = cross(d, r);
}
// Where the eye ray through the quad point p meets frame f's image plane, in frame uv.
vec2 frameUv(vec2 f, vec3 eye, vec3 p) {
  vec3 d = hemiOctDecode(f / (uFrames - 1.0));
  vec3 r; vec3 u;
  viewBasis(d, r, u);
  vec3 w = p - eye;
  float den = dot(w, d);
  float t = abs(den) > 1e-6 ? -dot(eye, d) / den : 1.0;
  vec3 hit = eye + w * t;
  return vec2(dot(hit, r), dot(hit, u)) / (2.0 * uRadius) + 0.5;
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
  vec3 r; vec3 u;
  viewBasis(view, r, u);
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
  vUv0 = frameUv(vFrame0, eyeL, local);
  vUv1 = frameUv(vFrame1, eyeL, local);
  vUv2 = frameUv(vFrame2, eyeL, local);
  vRotX = rot[0]; vRotY = rot[1]; vRotZ = rot[2];
#include <fog_vertex>
}`;

const IMPOSTOR_FRAGMENT = /* glsl */ `
uniform sampler2D uColor;
uniform sampler2D uNormal;
uniform float uFrames;
uniform float uCellPx;
uniform float uAlphaTest;
uniform float uCoverage;
uniform vec3 uSunDir;
uniform vec3 uSunColor;
uniform vec3 uSky;
uniform vec3 uGround;
varying vec2 vUv0;
varying vec2 vUv1;
varying vec2 vUv2;
varying vec2 vFrame0;
varying vec2 vFrame1;
varying vec2 vFrame2;
varying vec3 vWeights;
varying vec3 vRotX;
varying vec3 vRotY;
varying vec3 vRotZ;
#include <common>
#include <fog_pars_fragment>

vec2 atlasUv(vec2 frame, vec2 uv) {
  float e = 0.5 / uCellPx;
  return (frame + clamp(uv, e, 1.0 - e)) / uFrames;
}
float inside(vec2 uv) {
  return step(0.0, uv.x) * step(uv.x, 1.0) * step(0.0, uv.y) * step(uv.y, 1.0);
}
void main() {
  vec2 a0 = atlasUv(vFrame0, vUv0);
  vec2 a1 = atlasUv(vFrame1, vUv1);
  vec2 a2 = atlasUv(vFrame2, vUv2);
  // A sample outside its frame's square is empty.
  vec4 c0 = texture2D(uColor, a0) * inside(vUv0);
  vec4 c1 = texture2D(uColor, a1) * inside(vUv1);
  vec4 c2 = texture2D(uColor, a2) * inside(vUv2);
  // Sharpened blend: one frame dominates away from the frames' borders, so parts far from the
  // tree's centre (the trunk's foot, the crown's top) show less twice.
  vec3 w = vWeights * vWeights * vWeights;
  w /= max(w.x + w.y + w.z, 1e-6);
  vec4 c = c0 * w.x + c1 * w.y + c2 * w.z;
  if (c.a < uAlphaTest) discard;
  vec3 albedo = c.rgb / max(c.a, 1e-3);
  vec4 n0 = texture2D(uNormal, a0);
  vec4 n1 = texture2D(uNormal, a1);
  vec4 n2 = texture2D(uNormal, a2);
  // Normals are premultiplied by coverage (the colour's alpha) in the multisampled bake.
  vec3 nl = (n0.xyz * 2.0 - c0.a) * w.x + (n1.xyz * 2.0 - c1.a) * w.y + (n2.xyz * 2.0 - c2.a) * w.z;
  vec3 n = normalize(mat3(vRotX, vRotY, vRotZ) * nl + vec3(0.0, 1e-4, 0.0));
  vec3 irradiance = mix(uGround, uSky, n.y * 0.5 + 0.5) + uSunColor * max(dot(n, uSunDir), 0.0);
  gl_FragColor = vec4(albedo * irradiance * RECIPROCAL_PI, uCoverage > 0.5 ? c.a : 1.0);
#include <tonemapping_fragment>
#include <colorspace_fragment>
#include <fog_fragment>
}`;

/** The viewer's lights as the impostor's sky + ground + sun model (one definition: lighting.ts). */
export function viewerLights(): ImpostorLights {
  return impostorLights();
}

/** The impostor's material (works on a Mesh and on an InstancedMesh of the impostor quad). */
export function impostorMaterial(
  atlas: ImpostorAtlas,
  lights: ImpostorLights,
  options: ImpostorDrawOptions = {},
): ShaderMaterial {
  const coverage = options.coverage ?? false;
  const material = new ShaderMaterial({
    vertexShader: IMPOSTOR_VERTEX,
    fragmentShader: IMPOSTOR_FRAGMENT,
    uniforms: UniformsUtils.merge([
      UniformsLib.fog,
      {
        uColor: { value: null },
        uNormal: { value: null },
        uFrames: { value: atlas.frames },
        uCellPx: { value: atlas.cellPx },
        uCentre: { value: atlas.centre.clone() },
        uRadius: { value: atlas.radius },
        // Below ½: the 3-frame blend and bilinear filtering thin out leaves a pixel or two wide.
        // With coverage, a texel a quarter covered still draws, blended by its coverage.
        uAlphaTest: { value: coverage ? 0.25 : 0.35 },
        uCoverage: { value: coverage ? 1 : 0 },
        uSunDir: { value: lights.sunDir.clone() },
        uSunColor: { value: lights.sunColor.clone() },
        uSky: { value: lights.sky.clone() },
        uGround: { value: lights.ground.clone() },
      },
    ]),
    fog: true,
    side: DoubleSide,
    transparent: coverage,
  });
  // Set after the merge: merging clones uniform values, and render-target textures cannot be.
  material.uniforms.uColor!.value = atlas.color;
  material.uniforms.uNormal!.value = atlas.normal;
  return material;
}

/** The impostor quad: a unit square in x, y (the vertex shader turns it to the eye). */
export function impostorGeometry(): PlaneGeometry {
  return new PlaneGeometry(1, 1);
}
