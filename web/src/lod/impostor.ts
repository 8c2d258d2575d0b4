/**
 * Octahedral impostors (docs/user-guide.md, Levels of detail), baked in the browser:
 *
 * * **Bake**: the LOD0 tree is rendered from the `n × n` view directions of a hemi-octahedral
 *   grid (`hemiOct.ts`) with an orthographic camera fitted to its bounding sphere, one frame per
 *   atlas cell, into one multisampled render target with two colour attachments (one draw per
 *   frame): albedo + coverage (unlit, premultiplied) and object-space normals (`n · 0.5 + 0.5`,
 *   leaves' back faces flipped toward the camera, premultiplied by coverage) with the depth
 *   toward the eye in the normal's alpha (`h / r · 0.5 + 0.5`, h the signed distance from the
 *   frame's image plane through the centre, premultiplied too).
 * * **Draw**: a camera-facing quad (per instance in the forest) whose vertex shader finds the
 *   3 frames around the view direction in the tree's own frame and their barycentric weights.
 *   Each fragment casts its eye ray into each of the 3 frames and marches it through that
 *   frame's depth (parallax occlusion mapping, refined by bisection: `hemiOct.ts`
 *   `frameRay`/`parallaxHit` are the same maths) to the point where it meets the surface that
 *   frame saw, so the 3 frames sample the same point of the tree and agree: one trunk, not two
 *   half-transparent ones. (Projecting onto each frame's plane through the centre instead, as
 *   this did before, put everything off that plane, such as the trunk's foot seen from a frame
 *   above the horizon, in a different place per frame.) Depth parallax was chosen over the
 *   nearest frame with a dithered cross-fade: the cross-fade still shows both frames' trunks,
 *   stippled, wherever it fades, and without it the image jumps by a frame's angle. The shader
 *   blends the 3 samples, alpha-tests, and relights with the blended normal (hemisphere light +
 *   sun, the viewer's lights), so the impostor follows the scene's lighting.
 */
import {
  Color,
  DepthTexture,
  DoubleSide,
  FloatType,
  FrontSide,
  GLSL3,
  InstancedMesh,
  LinearFilter,
  Matrix4,
  Mesh,
  NearestFilter,
  OrthographicCamera,
  PlaneGeometry,
  RGBAFormat,
  Scene,
  ShaderMaterial,
  UniformsLib,
  UniformsUtils,
  UnsignedByteType,
  Vector3,
  Vector4,
  WebGLRenderTarget,
  type BufferGeometry,
  type Sphere,
  type Texture,
  type WebGLRenderer,
} from 'three';
import {
  impostorLights,
  type ImpostorLights,
  LEAF_TRANSLUCENCY,
  wrapInstances,
} from 'sylva-trees/viewer';
import { frameDirection, viewBasis } from './hemiOct';
import bakeVertex from './shaders/impostorBake.vert.glsl?raw';
import bakeFragment from './shaders/impostorBake.frag.glsl?raw';
import impostorVertex from './shaders/impostor.vert.glsl?raw';
import impostorFragment from './shaders/impostor.frag.glsl?raw';
import impostorVaryings from './shaders/impostorVaryings.glsl?raw';

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
  /**
   * Direction toward the sun in tree space, for a tree drawn with shadows (the viewer): each
   * texel then stores the share of the sun it receives (the tree shadowing itself, as LOD0 is
   * in a scene with shadows). Absent (the forest, drawn without shadows): fully lit.
   */
  sunDirection?: Vector3 | undefined;
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
  /** Light terms, premultiplied by coverage: r the sun's share, g 1 on leaves (0 on bark). */
  light: Texture;
  frames: number;
  cellPx: number;
  /** Bounding sphere the frames were fitted to (tree space). */
  centre: Vector3;
  radius: number;
  /** Milliseconds spent baking (CPU time of the render calls). */
  bakeMs: number;
  /**
   * The colour atlas's pixels read back (`size²` RGBA8, bottom row first, linear albedo
   * premultiplied by coverage), for the LOD export; valid until `dispose`.
   */
  readColor(): Uint8Array;
  dispose(): void;
}

function bakeMaterial(part: BakePart, radius: number): ShaderMaterial {
  const material = new ShaderMaterial({
    vertexShader: bakeVertex,
    fragmentShader: bakeFragment,
    uniforms: {
      uColor: { value: new Color() },
      uMap: { value: null },
      uUseMap: { value: 0 },
      uRadius: { value: 0 },
      uLeaf: { value: 0 },
      uSunDepth: { value: null },
      uSunMatrix: { value: new Matrix4() },
      uSunTexel: { value: 1 / SUN_MAP_PX },
      uSunBias: { value: 0 },
      uSunDepthBias: { value: 0.002 },
      uUseSun: { value: 0 },
      uSunDir: { value: new Vector3(0, 1, 0) },
    },
    glslVersion: GLSL3,
    vertexColors: part.vertexColors ?? false,
    side: part.doubleSided ? DoubleSide : FrontSide,
  });
  dressBakeMaterial(material, part, radius);
  return material;
}

/** Points a bake material at `part` and a tree of `radius` (no sun). */
function dressBakeMaterial(material: ShaderMaterial, part: BakePart, radius: number): void {
  const u = material.uniforms;
  (u.uColor!.value as Color).set(part.color);
  u.uMap!.value = part.map;
  u.uUseMap!.value = part.map ? 1 : 0;
  u.uRadius!.value = radius;
  u.uLeaf!.value = part.doubleSided ? 1 : 0;
  u.uSunDepth!.value = null;
  (u.uSunMatrix!.value as Matrix4).identity();
  u.uSunBias!.value = radius * 0.004;
  u.uSunDepthBias!.value = 0.002;
  u.uUseSun!.value = 0;
  u.uSunDir!.value = new Vector3(0, 1, 0);
}

/**
 * Bake materials kept per renderer and used again by its later bakes: three.js releases a
 * program when its last material is disposed, and compiling the bake's programs again for every
 * tree took about 0.3 s of each forest tree's bake in software WebGL. Per kind of part (vertex
 * colours, sides), the i-th part of that kind in a bake gets the i-th material.
 */
const keptBakeMaterials = new WeakMap<WebGLRenderer, Map<string, ShaderMaterial[]>>();

/** The bake materials of `parts` for `renderer` (see `keptBakeMaterials`). */
function bakeMaterials(
  renderer: WebGLRenderer,
  parts: BakePart[],
  radius: number,
): ShaderMaterial[] {
  let kept = keptBakeMaterials.get(renderer);
  if (!kept) {
    kept = new Map();
    keptBakeMaterials.set(renderer, kept);
  }
  const used = new Map<string, number>();
  return parts.map((part) => {
    const key = `${part.vertexColors ? 1 : 0}${part.doubleSided ? 1 : 0}`;
    const i = used.get(key) ?? 0;
    used.set(key, i + 1);
    const list = kept.get(key) ?? [];
    kept.set(key, list);
    const material = list[i];
    if (material) {
      dressBakeMaterial(material, part, radius);
      return material;
    }
    const fresh = bakeMaterial(part, radius);
    list.push(fresh);
    return fresh;
  });
}

/**
 * Renders `parts` from the `frames × frames` hemi-octahedral views fitted to `sphere` into a
 * colour, a normal and a light atlas. Restores the renderer's target, viewport and clear state.
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
  const r = Math.max(sphere.radius, 1e-3);
  const scene = new Scene();
  const materials = bakeMaterials(renderer, parts, r);
  const meshes: Mesh[] = [];
  for (const [k, part] of parts.entries()) {
    const material = materials[k]!;
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
  // One target with three colour attachments (albedo, normal, light): each frame is drawn once.
  const target = new WebGLRenderTarget(size, size, {
    count: 3,
    format: RGBAFormat,
    type: UnsignedByteType,
    minFilter: LinearFilter,
    magFilter: LinearFilter,
    generateMipmaps: false,
    depthBuffer: true,
    samples: options.samples ?? 4,
  });
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
  let sun: WebGLRenderTarget | null = null;
  try {
    if (options.sunDirection) {
      sun = sunDepthMap(renderer, scene, materials, sphere, options.sunDirection);
    }
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
    // The materials stay for the next bake (keptBakeMaterials), holding no texture of this one.
    for (const m of materials) {
      m.uniforms.uMap!.value = null;
      m.uniforms.uSunDepth!.value = null;
    }
    for (const mesh of meshes) if (mesh instanceof InstancedMesh) mesh.dispose();
    sun?.dispose();
  }
  return {
    color: target.textures[0]!,
    normal: target.textures[1]!,
    light: target.textures[2]!,
    frames,
    cellPx,
    centre: sphere.center.clone(),
    radius: r,
    bakeMs: performance.now() - t0,
    readColor: () => {
      const pixels = new Uint8Array(size * size * 4);
      renderer.readRenderTargetPixels(target, 0, 0, size, size, pixels, undefined, 0);
      return pixels;
    },
    dispose: () => target.dispose(),
  };
}

/**
 * How much sunlight a leaf lets through from behind (packages/sylva-trees/src/viewer/lighting.ts
 * `LEAF_TRANSLUCENCY`, which the package does not export under that name).
 */
const LEAF_THROUGH = 0.45;

/** Edge of the sun's depth map (texels) the bake's shadows are taken from. */
const SUN_MAP_PX = 1024;

/**
 * Draws the depth of `scene` (the bake's parts) seen from the sun along `toSun` with an
 * orthographic camera fitted to `sphere`, and points the bake `materials` at it. Returns the
 * depth target (the caller disposes of it after the bake).
 */
function sunDepthMap(
  renderer: WebGLRenderer,
  scene: Scene,
  materials: ShaderMaterial[],
  sphere: Sphere,
  toSun: Vector3,
): WebGLRenderTarget {
  const r = Math.max(sphere.radius, 1e-3);
  const target = new WebGLRenderTarget(SUN_MAP_PX, SUN_MAP_PX, {
    depthBuffer: true,
    depthTexture: new DepthTexture(SUN_MAP_PX, SUN_MAP_PX, FloatType),
    minFilter: NearestFilter,
    magFilter: NearestFilter,
  });
  target.depthTexture!.minFilter = NearestFilter;
  target.depthTexture!.magFilter = NearestFilter;
  const dir = toSun.clone().normalize();
  const camera = new OrthographicCamera(-r, r, r, -r, r, r * 3);
  camera.position.copy(sphere.center).addScaledVector(dir, 2 * r);
  camera.up.set(Math.abs(dir.y) > 0.99 ? 1 : 0, Math.abs(dir.y) > 0.99 ? 0 : 1, 0);
  camera.lookAt(sphere.center);
  camera.updateMatrixWorld();
  renderer.setRenderTarget(target);
  renderer.clear(true, true, true);
  // The map's own pass samples no map (a texture may not be read while it is drawn into).
  renderer.render(scene, camera);
  const matrix = new Matrix4().multiplyMatrices(camera.projectionMatrix, camera.matrixWorldInverse);
  for (const m of materials) {
    m.uniforms.uSunDepth!.value = target.depthTexture;
    m.uniforms.uSunMatrix!.value = matrix;
    m.uniforms.uUseSun!.value = 1;
    m.uniforms.uSunDir!.value = dir;
    // About 3 cm on a 5 m tree, as the viewer's shadow bias (lighting.ts).
    m.uniforms.uSunDepthBias!.value = 0.003;
  }
  return target;
}

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
    vertexShader: impostorVaryings + impostorVertex,
    fragmentShader: impostorVaryings + impostorFragment,
    uniforms: UniformsUtils.merge([
      UniformsLib.fog,
      {
        uColor: { value: null },
        uNormal: { value: null },
        uLight: { value: null },
        uLeafEmissive: { value: LEAF_TRANSLUCENCY },
        uLeafTranslucency: { value: LEAF_THROUGH },
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
  material.uniforms.uLight!.value = atlas.light;
  return material;
}

/** The impostor quad: a unit square in x, y (the vertex shader turns it to the eye). */
export function impostorGeometry(): PlaneGeometry {
  return new PlaneGeometry(1, 1);
}
