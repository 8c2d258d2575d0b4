/**
 * Wind animation on the GPU: patches three.js materials (bark, leaves and their shadow depth
 * materials) with the vertex displacement of `wind.math.ts` (GPU Gems 3, ch. 16: main bending,
 * branch and twig bending from smooth triangle waves, leaf flutter, gusts). Lighting, shadows
 * and normal maps are untouched: only `transformed` (the object-space position) moves.
 *
 * Time comes only from the `uWindTime` uniform, driven by a `WindClock` (real time unless
 * paused; tests set it), so a given frame can be rendered again exactly.
 *
 * Per-vertex data (bark): the core's `TreeMesh.wind` (8 floats per vertex) wrapped as one
 * interleaved buffer with two vec4 views, `windPivot` (pivot xyz, level) and `windParams`
 * (phase, stiffness, distance, radius). Without it (`uWindTree.z = 0`) the bark gets the main
 * bending and the position-based branch sway only. Leaves (an `InstancedMesh`, or the viewer's
 * pulled leaves, whose `instanceMatrix` is read from a texture) take their attachment point
 * from `instanceMatrix[3].xyz`.
 */
import {
  type BufferGeometry,
  InterleavedBuffer,
  InterleavedBufferAttribute,
  MeshDepthMaterial,
  Vector2,
  Vector4,
  type IUniform,
  type Material,
  type WebGLProgramParametersWithUniforms,
} from 'three';
import type { Bounds } from '../core/types';
import { BRANCH_SWAY, LEAF_FLUTTER, MAIN_BEND, TWIG_ANGLE, type WindFrame } from './wind.math';
import commonSrc from './shaders/windCommon.vert.glsl?raw';
import barkParsSrc from './shaders/windBarkPars.vert.glsl?raw';
import leafParsSrc from './shaders/windLeafPars.vert.glsl?raw';
import barkVertexSrc from './shaders/windBark.vert.glsl?raw';
import leafVertexSrc from './shaders/windLeaf.vert.glsl?raw';
import {
  DEFAULT_WIND,
  GUST_FREQUENCY,
  initialWind,
  windDirectionVector,
  type WindSettings,
} from './windSettings';

/** Floats per vertex in the core's wind buffer. */
export const WIND_STRIDE = 8;

/** The shared uniforms (one object per viewer; every patched material points at it). */
export interface WindUniforms {
  uWindTime: IUniform<number>;
  /** Unit `[x, z]` the wind blows toward. */
  uWindDirection: IUniform<Vector2>;
  uWindStrength: IUniform<number>;
  /** Amplitude 0..1, frequency Hz. */
  uWindGust: IUniform<Vector2>;
  /** 1 on, 0 off. */
  uWindEnabled: IUniform<number>;
  /** Tree height (m), crown radius (m), 1 when the bark has per-vertex wind data, unused. */
  uWindTree: IUniform<Vector4>;
  /** Index signature for three's uniform maps. */
  [name: string]: IUniform;
}

/**
 * Which displacement a material gets: the bark's, the leaves' (flutter, then their anchor's
 * sway), or the organs' (flowers, fruit, buds: the leaves' without the flutter, rigid parts
 * carried by their anchor).
 */
export type WindKind = 'bark' | 'leaves' | 'organs';

/** Fresh uniforms with the default settings and a 10 m tree. */
export function createWindUniforms(): WindUniforms {
  const [x, z] = windDirectionVector(DEFAULT_WIND.direction);
  return {
    uWindTime: { value: 0 },
    uWindDirection: { value: new Vector2(x, z) },
    uWindStrength: { value: DEFAULT_WIND.strength },
    uWindGust: { value: new Vector2(DEFAULT_WIND.gust, GUST_FREQUENCY) },
    uWindEnabled: { value: DEFAULT_WIND.enabled ? 1 : 0 },
    uWindTree: { value: new Vector4(10, 3, 0, 0) },
  };
}

const f = (x: number): string => x.toFixed(6);

/** The shaders' constants, from the TS mirror (`wind.math.ts`); GLSL in `shaders/wind*.glsl`. */
const WIND_DEFINES = [
  `#define WIND_MAIN_BEND ${f(MAIN_BEND)}`,
  `#define WIND_BRANCH_SWAY ${f(BRANCH_SWAY)}`,
  `#define WIND_TWIG_ANGLE ${f(TWIG_ANGLE)}`,
  `#define WIND_LEAF_FLUTTER ${f(LEAF_FLUTTER)}`,
].join('\n');

/** Uniforms and functions shared by every wind shader (mirrors `wind.math.ts`). */
export const WIND_COMMON_GLSL = `${WIND_DEFINES}\n${commonSrc}`;

/** Per-vertex attributes and twig bending of the bark. */
export const WIND_BARK_PARS_GLSL = barkParsSrc;

/** Leaf flutter (leaf units, along the blade's normal). */
export const WIND_LEAF_PARS_GLSL = leafParsSrc;

/** Bark displacement, after `#include <begin_vertex>` (object space = tree space). */
export const WIND_BARK_VERTEX_GLSL = barkVertexSrc;

/**
 * Leaf displacement, after `#include <begin_vertex>`: flutter in leaf space, then the attachment
 * point's branch sway and the main bending in tree space, mapped back to leaf space.
 */
export const WIND_LEAF_VERTEX_GLSL = leafVertexSrc;

/** Marker of a patched shader (tests and double-patch guard). */
export const WIND_MARKER = '// sylva-wind';

/** Injects the wind chunks into a vertex shader and binds the shared uniforms. */
export function patchWindShader(
  shader: Pick<WebGLProgramParametersWithUniforms, 'vertexShader' | 'uniforms'>,
  uniforms: WindUniforms,
  kind: WindKind,
): void {
  if (shader.vertexShader.includes(WIND_MARKER)) return;
  const pars = kind === 'bark' ? WIND_BARK_PARS_GLSL : WIND_LEAF_PARS_GLSL;
  const body = kind === 'bark' ? WIND_BARK_VERTEX_GLSL : WIND_LEAF_VERTEX_GLSL;
  const common = '#include <common>';
  const begin = '#include <begin_vertex>';
  if (!shader.vertexShader.includes(common) || !shader.vertexShader.includes(begin)) {
    throw new Error('wind: the vertex shader has no <common>/<begin_vertex> chunk');
  }
  const rigid = kind === 'organs' ? '#define WIND_NO_FLUTTER\n' : '';
  shader.vertexShader = shader.vertexShader
    .replace(common, `${common}\n${WIND_MARKER} ${kind}\n${rigid}${WIND_COMMON_GLSL}${pars}`)
    .replace(begin, `${begin}\n${body}`);
  Object.assign(shader.uniforms, uniforms);
}

/** Makes `material` wind-animated (its program is cached per kind). */
export function applyWind(material: Material, uniforms: WindUniforms, kind: WindKind): void {
  const previous = material.onBeforeCompile.bind(material);
  material.onBeforeCompile = (shader, renderer) => {
    previous(shader, renderer);
    patchWindShader(shader, uniforms, kind);
  };
  material.customProgramCacheKey = () => `sylva-wind-${kind}`;
  material.needsUpdate = true;
}

/** A shadow depth material that moves like `kind` (three copies map/alphaTest/side onto it). */
export function createWindDepthMaterial(uniforms: WindUniforms, kind: WindKind): MeshDepthMaterial {
  const material = new MeshDepthMaterial();
  applyWind(material, uniforms, kind);
  return material;
}

/**
 * Wraps the core's wind buffer (8 floats per vertex) as `windPivot` + `windParams` without
 * copying; returns whether the geometry has per-vertex wind data now.
 */
export function attachWindAttributes(
  geometry: BufferGeometry,
  wind: Float32Array | undefined,
): boolean {
  const vertices = geometry.getAttribute('position')?.count ?? 0;
  if (!wind || vertices === 0 || wind.length !== vertices * WIND_STRIDE) return false;
  const buffer = new InterleavedBuffer(wind, WIND_STRIDE);
  geometry.setAttribute('windPivot', new InterleavedBufferAttribute(buffer, 4, 0));
  geometry.setAttribute('windParams', new InterleavedBufferAttribute(buffer, 4, 4));
  return true;
}

/** Shader time: follows real time unless paused; tests and the debug hook set it directly. */
export class WindClock {
  time = 0;
  paused = false;
  private last: number | null = null;

  /** Advances by the real time since the last running tick (capped at 0.1 s per frame). */
  tick(nowMs: number, running = true): number {
    if (!running || this.paused) {
      this.last = null;
      return this.time;
    }
    if (this.last !== null) this.time += Math.min(Math.max(nowMs - this.last, 0), 100) / 1000;
    this.last = nowMs;
    return this.time;
  }

  /** Jumps to `seconds`. */
  set(seconds: number): void {
    this.time = Number.isFinite(seconds) ? seconds : 0;
    this.last = null;
  }
}

/** Height and crown radius of a tree from its bounds (no per-vertex work). */
export function treeExtent(bounds: Bounds): { height: number; radius: number } {
  const { min, max } = bounds;
  return {
    height: Math.max(max[1], 0.1),
    radius: Math.max(Math.abs(min[0]), Math.abs(max[0]), Math.abs(min[2]), Math.abs(max[2]), 0.1),
  };
}

/** Owns the uniforms, clock, settings and shadow materials of one viewer. */
export class WindController {
  readonly uniforms = createWindUniforms();
  readonly clock = new WindClock();
  private current: WindSettings = initialWind();
  private readonly depth = new Map<string, MeshDepthMaterial>();

  /** `onChange` asks for a new frame (settings or time changed). */
  constructor(private readonly onChange: () => void = () => undefined) {
    this.sync();
  }

  /** The current settings. */
  get settings(): WindSettings {
    return { ...this.current };
  }

  /** Whether frames change with real time (the viewer keeps rendering). */
  get animating(): boolean {
    return this.current.enabled && !this.clock.paused && this.current.strength > 0;
  }

  /** Whether the current tree's bark has the core's per-vertex data. */
  get hasVertexData(): boolean {
    return this.uniforms.uWindTree.value.z > 0.5;
  }

  /** Applies (partial) settings. */
  set(settings: Partial<WindSettings>): void {
    this.current = { ...this.current, ...settings };
    this.sync();
    this.onChange();
  }

  private sync(): void {
    const u = this.uniforms;
    const [x, z] = windDirectionVector(this.current.direction);
    u.uWindDirection.value.set(x, z);
    u.uWindStrength.value = this.current.strength;
    u.uWindGust.value.set(this.current.gust, GUST_FREQUENCY);
    u.uWindEnabled.value = this.current.enabled ? 1 : 0;
    this.clock.paused = this.current.paused;
  }

  /** Sets the shader time (seconds). */
  setTime(seconds: number): void {
    this.clock.set(seconds);
    this.uniforms.uWindTime.value = this.clock.time;
    this.onChange();
  }

  /** A new tree: its size, and whether its bark carries per-vertex wind data. */
  setTree(bounds: Bounds, hasVertexData: boolean): void {
    const { height, radius } = treeExtent(bounds);
    this.uniforms.uWindTree.value.set(height, radius, hasVertexData ? 1 : 0, 0);
  }

  /** Once per animation frame, before rendering: advances the clock. */
  tick(nowMs: number): void {
    this.uniforms.uWindTime.value = this.clock.tick(nowMs, this.animating);
  }

  /** Patches a material. */
  apply(material: Material, kind: WindKind): void {
    applyWind(material, this.uniforms, kind);
  }

  /**
   * The (shared) shadow depth material for `kind`; `variant` names another one of the same kind
   * (pulled leaves patch theirs further).
   */
  depthMaterial(kind: WindKind, variant = ''): MeshDepthMaterial {
    const key = `${kind}${variant}`;
    let material = this.depth.get(key);
    if (!material) {
      material = createWindDepthMaterial(this.uniforms, kind);
      this.depth.set(key, material);
    }
    return material;
  }

  /** The uniform values as a `wind.math.ts` frame (tests, CPU-side mirrors). */
  frame(): WindFrame {
    const u = this.uniforms;
    return {
      time: u.uWindTime.value,
      direction: [u.uWindDirection.value.x, u.uWindDirection.value.y],
      strength: u.uWindStrength.value,
      gust: [u.uWindGust.value.x, u.uWindGust.value.y],
      enabled: u.uWindEnabled.value > 0.5,
      height: u.uWindTree.value.x,
      radius: u.uWindTree.value.y,
    };
  }

  dispose(): void {
    for (const material of this.depth.values()) material.dispose();
    this.depth.clear();
  }
}
