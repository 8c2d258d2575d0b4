/**
 * The forest view's three.js side: N trees of a few varieties on a ground plane. Per variety and
 * level there is one InstancedMesh per material (LOD0 bark + leaves, LOD1 bark + leaves, LOD2
 * bark + billboard cloud, impostor quad): 7 meshes per variety, the bark and leaves of a level
 * sharing one instance buffer. Every frame `assignLods` (layout.ts) buckets the trees by
 * distance and writes their matrices into those preallocated buffers; only the written range is
 * uploaded and `.count` set, so the number of draw calls is bounded by
 * `varieties × 7 + 1` (the ground) whatever N is.
 */
import { SceneLights, wrapInstances } from 'sylva-trees/viewer';
import { fitToContainer } from '../viewer/cameraView';
import { isSoftwareRenderer, webglRendererName } from '../viewer/renderQuality';
import type { InstancedMesh } from 'three';
import {
  Color,
  DynamicDrawUsage,
  Fog,
  Frustum,
  InstancedBufferAttribute,
  Matrix4,
  Mesh,
  MeshStandardMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  Scene,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { buildVariety, type Variety } from './variety';
import { placeForest } from './ecology';
import { drawNow } from './frames';
import { switchDistances } from '../lod/selection';
import type { LodBuffers } from 'sylva-trees/worker';
import {
  assignLods,
  createBuckets,
  FOREST_LEVELS,
  type ForestLayout,
  type LodBuckets,
} from './layout';

/** Meshes (so draw calls) per variety: 3 levels × 2 materials + the impostor. */
export const MESHES_PER_VARIETY = 7;
/** Screen-size thresholds of the forest (see lod/selection.ts): more aggressive than the viewer. */
export const FOREST_THRESHOLDS = [0.6, 0.3, 0.12];
/** Upper bound of draw calls for `varieties` varieties: their meshes plus the ground. */
export function drawCallBound(varieties: number): number {
  return varieties * MESHES_PER_VARIETY + 1;
}

const SKY = '#dce6ec';
const GROUND = '#8f9a6e';
const FRAME_SAMPLES = 60;
/** Share of the pixel ratio a software renderer draws at while trees arrive. */
const ARRIVING_RESOLUTION = 0.5;

/** Numbers the overlay and the debug hook read. */
export interface ForestStats {
  trees: number;
  varieties: number;
  drawCalls: number;
  bound: number;
  triangles: number;
  /** Median time of the last frames drawn, each from its display frame to the next (ms). */
  frameMs: number;
  /** Median CPU time of LOD assignment + render (ms). */
  cpuMs: number;
  /** Median LOD assignment time (ms). */
  assignMs: number;
  /** Trees drawn per level (LOD0, LOD1, LOD2, impostor). */
  perLevel: number[];
  /** Trees drawn (inside the view). */
  visible: number;
}

/** What the debug hook's `forest()` returns. */
export interface ForestDebug {
  drawCalls: number;
  bound: number;
  instances: number;
  visible: number;
  perLevel: number[];
  frameMs: number;
  cpuMs: number;
  assignMs: number;
  varieties: number;
  expectedVarieties: number;
  bakeMs: number[];
  /** `performance.now()` when the forest view opened, and when each unique tree was shown. */
  openedAt: number;
  shownAt: number[];
  /** Generation workers in the forest's pool. */
  poolSize: number;
}

function median(values: number[]): number {
  if (values.length === 0) return 0;
  const s = [...values].sort((a, b) => a - b);
  return s[Math.floor(s.length / 2)]!;
}

/** See the module docs. */
export class ForestScene {
  readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly camera = new PerspectiveCamera(40, 1, 0.5, 4000);
  private readonly controls: OrbitControls;
  private readonly lights: SceneLights;
  private readonly ground: Mesh<PlaneGeometry, MeshStandardMaterial>;
  private readonly varieties: Variety[] = [];
  private meshes: InstancedMesh[][] = [];
  private attributes: InstancedBufferAttribute[] = [];
  private layout: ForestLayout | null = null;
  private buckets: LodBuckets | null = null;
  private count = 0;
  private seed = 1;
  private species = 1;
  private frameId = 0;
  private readonly frameTimes: number[] = [];
  private readonly cpuTimes: number[] = [];
  private readonly assignTimes: number[] = [];
  private readonly frustum = new Frustum();
  private readonly planes = new Float32Array(24);
  private readonly projView = new Matrix4();
  private radius = new Float32Array(0);
  private centreY = new Float32Array(0);
  private readonly resizeObserver: ResizeObserver;
  private disposed = false;
  private statsValue: ForestStats;
  /** Until the first tree is added the loop draws nothing. */
  private loading = true;
  /**
   * Whether the view changed since the last frame drawn: the forest is drawn on demand (the
   * camera moved, trees were added or placed again, the canvas resized), not at every display
   * frame. A software renderer shades a forest frame on the CPU (about 2 s on 2 cores), which
   * starved the generation workers of the trees still to come.
   */
  private dirty = true;
  /** When the last frame was drawn (its display frame's start), 0 once timed. */
  private drawnAt = 0;
  /** Start and duration of the last frame drawn (ms). */
  private lastDraw = { at: 0, ms: 0 };
  /** When the first tree was added (ms), for `drawNow`. */
  private firstAddedAt = 0;
  /** Whether more trees are on their way (`setArriving`). */
  private arriving = false;
  /** Whether the renderer shades on the CPU (renderQuality.ts). */
  private readonly software = isSoftwareRenderer(webglRendererName() ?? '');
  /** Trees received and not yet added (`enqueue`). */
  private readonly arrivals: {
    lods: LodBuffers;
    tree: { id: number; species: number };
    added: () => void;
  }[] = [];

  constructor(private readonly container: HTMLElement) {
    this.renderer = new WebGLRenderer({ antialias: false });
    this.renderer.setPixelRatio(this.pixelRatio());
    this.renderer.domElement.dataset.testid = 'forest-canvas';
    container.appendChild(this.renderer.domElement);
    this.scene.background = new Color(SKY);
    this.scene.fog = new Fog(SKY, 150, 900);
    // The viewer's sky light and sun (lighting.ts), without shadows over a forest.
    this.lights = new SceneLights(this.scene, this.renderer, { shadows: false });
    this.ground = new Mesh(
      new PlaneGeometry(1, 1),
      new MeshStandardMaterial({ color: GROUND, roughness: 1 }),
    );
    this.ground.rotation.x = -Math.PI / 2;
    this.scene.add(this.ground);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.maxPolarAngle = Math.PI * 0.49;
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', this.invalidate);
    this.statsValue = this.emptyStats();
    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.resize();
    this.loop();
  }

  /**
   * Queues unique tree `tree` (`id` and `species` as `uniqueTrees` made it) with its levels; it
   * is added at the start of the next frame with every tree that arrived meanwhile (the forest
   * placed again once for all of them), then `added` is called and the forest is drawn. Each
   * addition bakes an impostor, which waits for the frame the GPU is still drawing: added one
   * by one as they arrived, a software renderer drew a whole forest frame (2 s) per tree.
   */
  enqueue(lods: LodBuffers, tree: { id: number; species: number }, added: () => void): void {
    this.arrivals.push({ lods, tree, added });
  }

  /**
   * Tells the scene whether more trees are on their way. Meanwhile frames are spaced out
   * (`drawNow`, frames.ts) and a software renderer draws at `ARRIVING_RESOLUTION`: it shades each
   * pixel on the CPU the generation workers need (a forest frame at 1000×700 took 1.7-2 s on 2
   * cores).
   */
  setArriving(arriving: boolean): void {
    this.arriving = arriving;
    this.renderer.setPixelRatio(this.pixelRatio());
    this.resize();
  }

  /** The canvas's pixel ratio (see `setArriving`). */
  private pixelRatio(): number {
    const full = Math.min(window.devicePixelRatio, 1.5);
    return this.software && this.arriving ? full * ARRIVING_RESOLUTION : full;
  }

  /** Adds the queued trees (see `enqueue`); starts drawing after the first. */
  private addArrivals(): void {
    if (this.arrivals.length === 0) return;
    const batch = this.arrivals.splice(0);
    for (const { lods, tree } of batch)
      this.varieties.push(buildVariety(lods, tree, this.renderer));
    this.rebuild();
    if (this.loading) this.firstAddedAt = performance.now();
    this.loading = false;
    for (const { added } of batch) added();
  }

  /** Number of varieties added. */
  get varietyCount(): number {
    return this.varieties.length;
  }

  /** Impostor bake times (ms) per variety. */
  get bakeMs(): number[] {
    return this.varieties.map((v) => v.atlas.bakeMs);
  }

  /** Sets the number of trees (places them again, keeps the seed and species map). */
  setCount(n: number, seed = this.seed, species = this.species): void {
    this.count = Math.max(0, Math.floor(n));
    this.seed = seed;
    this.species = Math.max(1, species);
    this.rebuild();
  }

  /** The latest stats. */
  stats(): ForestStats {
    return this.statsValue;
  }

  /** Places the camera `distance` m from the forest centre (tests). */
  setCameraDistance(distance: number): void {
    const dir = new Vector3().subVectors(this.camera.position, this.controls.target).normalize();
    this.camera.position.copy(this.controls.target).addScaledVector(dir, distance);
    this.controls.update();
  }

  /** Stops the loop and frees every GPU resource. */
  dispose(): void {
    this.disposed = true;
    cancelAnimationFrame(this.frameId);
    this.resizeObserver.disconnect();
    this.controls.dispose();
    this.disposeInstances();
    for (const v of this.varieties) for (const d of v.disposables) d.dispose();
    this.ground.geometry.dispose();
    this.ground.material.dispose();
    this.lights.dispose();
    this.renderer.dispose();
    this.renderer.domElement.remove();
  }

  private emptyStats(): ForestStats {
    return {
      trees: 0,
      varieties: 0,
      drawCalls: 0,
      bound: drawCallBound(0),
      triangles: 0,
      frameMs: 0,
      cpuMs: 0,
      assignMs: 0,
      perLevel: [0, 0, 0, 0],
      visible: 0,
    };
  }

  private disposeInstances(): void {
    for (const list of this.meshes) {
      for (const m of list) {
        this.scene.remove(m);
        m.dispose();
      }
    }
    this.meshes = [];
    this.attributes = [];
  }

  /** New layout and instanced meshes for the current count and varieties. */
  private rebuild(): void {
    this.dirty = true;
    this.disposeInstances();
    const nv = this.varieties.length;
    if (nv === 0) return;
    this.layout = placeForest(
      this.count,
      this.varieties.map((v) => v.tree),
      { seed: this.seed, species: this.species },
    );
    this.buckets = createBuckets(this.layout, nv);
    this.radius = Float32Array.from(this.varieties.map((v) => v.sphere.radius));
    this.centreY = Float32Array.from(this.varieties.map((v) => v.sphere.center.y));
    for (let v = 0; v < nv; v++) {
      const variety = this.varieties[v]!;
      for (let l = 0; l < FOREST_LEVELS; l++) {
        const b = v * FOREST_LEVELS + l;
        const attribute = new InstancedBufferAttribute(this.buckets.matrices[b]!, 16);
        attribute.setUsage(DynamicDrawUsage);
        this.attributes[b] = attribute;
        const list: InstancedMesh[] = [];
        for (const part of variety.parts[l]!) {
          const mesh = wrapInstances(part.geometry, part.material, attribute, null, 0);
          mesh.visible = false;
          mesh.frustumCulled = false;
          list.push(mesh);
          this.scene.add(mesh);
        }
        this.meshes[b] = list;
      }
    }
    const half = this.layout.halfSize;
    this.ground.scale.set(half * 2 + 200, half * 2 + 200, 1);
    const r = this.radius[0] ?? 5;
    // Start at the forest's edge, looking in over the trees.
    this.controls.target.set(0, r, half * 0.5);
    this.camera.position.set(half * 0.15, r * 3.5, half + r * 4);
    this.camera.far = half * 4 + 1000;
    this.camera.updateProjectionMatrix();
    (this.scene.fog as Fog).far = Math.max(half * 2.2, 400);
    (this.scene.fog as Fog).near = Math.max(half * 0.4, 100);
    this.controls.maxDistance = half * 3 + 200;
    this.controls.update();
  }

  private resize(): void {
    fitToContainer(this.renderer, this.camera, this.container);
    this.dirty = true;
  }

  private loop = (): void => {
    if (this.disposed) return;
    this.frameId = requestAnimationFrame(this.loop);
    this.addArrivals();
    const now = performance.now();
    // A frame's time: from its display frame to the next one the browser could start.
    if (this.drawnAt > 0) {
      push(this.frameTimes, now - this.drawnAt);
      this.lastDraw = { at: this.drawnAt, ms: now - this.drawnAt };
      this.statsValue = { ...this.statsValue, frameMs: median(this.frameTimes) };
    }
    this.drawnAt = 0;
    // While trees are arriving, the GPU (the CPU, in software) is left to the bakes and the
    // generation workers (frames.ts).
    const { loading, dirty, arriving, software, firstAddedAt, lastDraw } = this;
    if (!drawNow({ loading, dirty, arriving, software, now, firstAddedAt, lastDraw })) return;
    this.dirty = false;
    this.drawnAt = now;
    this.renderFrame();
  };

  /** Asks for a frame (see `dirty`). */
  private readonly invalidate = (): void => {
    this.dirty = true;
  };

  /** Assigns levels, uploads the written ranges and draws. */
  renderFrame(): void {
    const t0 = performance.now();
    let visible = 0;
    const layout = this.layout;
    const buckets = this.buckets;
    if (layout && buckets) {
      this.camera.updateMatrixWorld();
      this.projView.multiplyMatrices(this.camera.projectionMatrix, this.camera.matrixWorldInverse);
      this.frustum.setFromProjectionMatrix(this.projView);
      this.frustum.planes.forEach((p, k) => {
        this.planes[k * 4] = p.normal.x;
        this.planes[k * 4 + 1] = p.normal.y;
        this.planes[k * 4 + 2] = p.normal.z;
        this.planes[k * 4 + 3] = p.constant;
      });
      const { out, back } = switchDistances(FOREST_THRESHOLDS, this.camera.fov);
      const p = this.camera.position;
      visible = assignLods(layout, buckets, {
        camera: [p.x, p.y, p.z],
        radius: this.radius,
        centreY: this.centreY,
        out,
        back,
        planes: this.planes,
      });
      push(this.assignTimes, performance.now() - t0);
      for (let b = 0; b < this.meshes.length; b++) {
        const n = buckets.counts[b]!;
        const attribute = this.attributes[b]!;
        if (n > 0) {
          attribute.clearUpdateRanges();
          attribute.addUpdateRange(0, n * 16);
          attribute.needsUpdate = true;
        }
        for (const mesh of this.meshes[b]!) {
          mesh.count = n;
          mesh.visible = n > 0;
        }
      }
    }
    this.renderer.render(this.scene, this.camera);
    push(this.cpuTimes, performance.now() - t0);
    const info = this.renderer.info.render;
    let triangles = 0;
    if (buckets) {
      this.varieties.forEach((v, vi) => {
        for (let l = 0; l < FOREST_LEVELS; l++) {
          triangles += buckets.counts[vi * FOREST_LEVELS + l]! * v.triangles[l]!;
        }
      });
    }
    this.statsValue = {
      trees: this.count,
      varieties: this.varieties.length,
      drawCalls: info.calls,
      bound: drawCallBound(this.varieties.length),
      triangles,
      frameMs: median(this.frameTimes),
      cpuMs: median(this.cpuTimes),
      assignMs: median(this.assignTimes),
      perLevel: buckets ? Array.from(buckets.perLevel) : [0, 0, 0, 0],
      visible,
    };
  }
}

function push(list: number[], value: number): void {
  list.push(value);
  if (list.length > FRAME_SAMPLES) list.shift();
}
