/**
 * Levels of detail in the app viewer, as an overlay on the TreeViewer (through its
 * `overlayHost()`, so the viewer needs no LOD code): LOD0 is the viewer's own tree; LOD1, LOD2 and
 * the impostor are built here from a `lods` request for the same parameters (in the app's
 * generation pool, `lodClient.ts`) and swapped in by screen size (Auto, with hysteresis) or
 * forced. The impostor is baked from LOD0 the first time it is needed. Everything here is dropped
 * when a new tree arrives and rebuilt for it.
 */
import { applyLeafCoverage, LEAF_INSTANCED_MATERIAL_KEY, leafTexture } from 'sylva-trees/viewer';
import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  Group,
  Mesh,
  MeshBasicMaterial,
  MeshStandardMaterial,
  Sphere,
  Vector3,
  type InstancedMesh,
  type Material,
  type Object3D,
  type Texture,
  type WebGLRenderer,
} from 'three';
import type { Edit, OrganSetBuffers, Params, TreeBuffers, VolumePrimitive } from 'sylva-trees/core';
import type { OverlayHost } from '../viewer/overlayHost';
import { bakeImpostor, impostorGeometry, impostorMaterial, viewerLights } from './impostor';
import { organBakeParts } from './organParts';
import type { ImpostorAtlas } from './impostor';
import { SUPERSEDED, type LodClient } from './lodClient';
import {
  BARK_COLOR,
  barkGeometry,
  barkMesh,
  cloudGeometry,
  cloudMaterial,
  clumpTexture,
  leafGeometry,
  leafMesh,
  treeSphere,
} from './lodObjects';
import { IMPOSTOR_LEVEL, screenFraction, selectLod } from './selection';
import { findBaseObjects, sphereOf } from './lodBase';
import type { LodBuffers } from 'sylva-trees/worker';

/** Auto (by screen size), a forced level 0..3, or (tests) nothing drawn. */
export type LodMode = 'auto' | 0 | 1 | 2 | 3 | 'hidden';

/** What the LOD panel shows. */
export interface LodState {
  mode: LodMode;
  /** Level on screen (0..3). */
  level: number;
  /** Triangles per level (LOD0, LOD1, LOD2, impostor); null until the levels are built. */
  triangles: number[] | null;
  /** Screen-size measure `R / (d tan(fov/2))` of the tree now. */
  screen: number;
  /** Bounding radius of the tree (m). */
  radius: number;
  /** Whether LOD1/LOD2 are built for the tree on screen. */
  ready: boolean;
  /** Impostor bake time (ms), null until baked. */
  bakeMs: number | null;
}

/** Where the LOD request's parameters come from (the app's current params, volumes, edits). */
export interface LodSource {
  params(): Params | null;
  volumes(): VolumePrimitive[] | undefined;
  /** The hand edits (absent: none): the levels are of the edited tree. */
  edits?(): readonly Edit[] | undefined;
}

const LEVEL_COUNT = 4;

/**
 * The levels are built this long after the last new tree (ms) unless a coarser level is wanted
 * sooner: while a slider is dragged the pool stays idle instead of regenerating every intermediate
 * tree next to the viewer's own worker.
 */
export const LOD_IDLE_MS = 3000;

/** See the module docs. */
export class LodController {
  private mode: LodMode = 'auto';
  private level = 0;
  private hash = '';
  /** The tree's organ sets as the viewer last received them. */
  private organs: OrganSetBuffers[] = [];
  private sphere = new Sphere(new Vector3(0, 4, 0), 5);
  private lods: LodBuffers | null = null;
  private levels: (Group | null)[] = [null, null, null, null];
  private atlas: ImpostorAtlas | null = null;
  private base: Object3D[] = [];
  private renderer: WebGLRenderer | null = null;
  private bakeScheduled = false;
  private readonly root = new Group();
  private readonly probe: Mesh;
  private owned: { dispose(): void }[] = [];
  private readonly probeParts: { dispose(): void }[];
  private readonly unsubscribe: () => void;
  private readonly unsubscribeHash: () => void;
  private leafMap: Texture | null = null;
  private last: LodState | null = null;
  private disposed = false;
  /** Hash of the tree whose levels were last requested, and the idle timer for the next one. */
  private requested = '';
  private idleTimer: ReturnType<typeof setTimeout> | null = null;
  /** `impostorAtlas` calls waiting for the levels of the tree on screen. */
  private waiters: { resolve(): void; reject(error: Error): void }[] = [];
  private readonly onChange = () => this.update();

  constructor(
    private readonly host: OverlayHost,
    private readonly client: LodClient,
    private readonly source: LodSource,
    private readonly onState: (state: LodState) => void,
  ) {
    this.root.name = 'sylva-lod';
    host.scene.add(this.root);
    // A one-triangle mesh that draws nothing: its onBeforeRender hands us the viewer's renderer,
    // which the impostor bake needs (outside of a render, see `scheduleBake`).
    const probeGeometry = new BufferGeometry();
    probeGeometry.setAttribute('position', new BufferAttribute(new Float32Array(9), 3));
    const probeMaterial = new MeshBasicMaterial({ colorWrite: false, depthWrite: false });
    this.probe = new Mesh(probeGeometry, probeMaterial);
    this.probe.frustumCulled = false;
    this.probe.onBeforeRender = (renderer) => {
      if (this.renderer !== renderer) {
        this.renderer = renderer;
        if (this.level === IMPOSTOR_LEVEL) this.scheduleBake();
      }
    };
    this.probeParts = [probeGeometry, probeMaterial];
    host.scene.add(this.probe);
    this.unsubscribe = host.onTree((buffers) => this.onTree(buffers));
    // The hash follows the buffers: the levels are requested once it is known.
    this.unsubscribeHash = host.onHash((hash) => {
      this.hash = hash;
      this.armIdle();
    });
    host.orbit.addEventListener('change', this.onChange);
  }

  /** Sets Auto or a forced level. */
  setMode(mode: LodMode): void {
    this.mode = mode;
    this.update();
  }

  /** Moves the camera to `distance` (m) from the orbit target along its current direction. */
  setCameraDistance(distance: number): void {
    const { camera, orbit } = this.host;
    const dir = new Vector3().subVectors(camera.position, orbit.target).normalize();
    if (dir.lengthSq() === 0) dir.set(0, 0, 1);
    orbit.maxDistance = Math.max(orbit.maxDistance, distance * 1.01);
    orbit.minDistance = Math.min(orbit.minDistance, distance * 0.99);
    camera.far = Math.max(camera.far, distance * 4);
    camera.updateProjectionMatrix();
    camera.position.copy(orbit.target).addScaledVector(dir, distance);
    orbit.update();
    this.update();
  }

  /** The current state (also sent to `onState` on every change). */
  state(): LodState {
    const t = this.lods?.meta.levels.map((l) => l.triangles);
    return {
      mode: this.mode,
      level: this.level,
      triangles: t ? [...t, 2] : null,
      screen: this.screenSize(),
      radius: this.sphere.radius,
      ready: this.lods !== null,
      bakeMs: this.atlas?.bakeMs ?? null,
    };
  }

  /**
   * The impostor atlas of the tree on screen and its levels, for the LOD export: the levels are
   * requested now (no idle wait) and the atlas baked now if it was not yet. Read the atlas at
   * once: a new tree disposes it. Rejects when the levels cannot be built.
   */
  async impostorAtlas(): Promise<{ atlas: ImpostorAtlas; lods: LodBuffers; sphere: Sphere }> {
    while (!this.lods || this.lods.meta.hash !== this.hash) {
      if (this.disposed) throw new Error('the LOD view was closed');
      const ready = new Promise<void>((resolve, reject) => this.waiters.push({ resolve, reject }));
      this.requestLods();
      await ready;
    }
    if (!this.atlas) {
      if (!this.renderer) throw new Error('the viewer has not drawn the tree yet');
      this.atlas = this.own(this.bake(this.renderer, this.lods));
      this.update();
    }
    return { atlas: this.atlas, lods: this.lods, sphere: this.sphere.clone() };
  }

  /** Settles the `impostorAtlas` waits (with `error`: rejects them). */
  private wake(error?: Error): void {
    const waiters = this.waiters;
    this.waiters = [];
    for (const w of waiters) {
      if (error) w.reject(error);
      else w.resolve();
    }
  }

  /** Removes every object and listener. */
  dispose(): void {
    this.disposed = true;
    this.wake(new Error('the LOD view was closed'));
    if (this.idleTimer !== null) clearTimeout(this.idleTimer);
    this.unsubscribe();
    this.unsubscribeHash();
    this.host.orbit.removeEventListener('change', this.onChange);
    this.clearLevels();
    this.setBaseVisible(true);
    this.host.scene.remove(this.root, this.probe);
    for (const o of this.probeParts) o.dispose();
  }

  private onTree(buffers: TreeBuffers): void {
    this.hash = buffers.meta.hash;
    // The flowers, fruit, catkins and buds come with new placements only.
    if (buffers.organs) this.organs = buffers.organs;
    this.base = findBaseObjects(this.host.scene, buffers, this.root, this.probe);
    // A drag's preview keeps the last full tree's sphere: sizing it loops over every leaf on
    // the main thread (a millisecond a step), and the full tree follows on release.
    if (!buffers.meta.preview) this.sphere = sphereOf(buffers);
    this.clearLevels();
    this.update();
    this.armIdle();
  }

  /** (Re)starts the idle wait before the levels are requested. */
  private armIdle(): void {
    if (this.idleTimer !== null) clearTimeout(this.idleTimer);
    this.idleTimer = setTimeout(() => this.requestLods(), LOD_IDLE_MS);
  }

  /** Asks the pool for the current tree's levels (once per tree). */
  private requestLods(): void {
    if (this.idleTimer !== null) clearTimeout(this.idleTimer);
    this.idleTimer = null;
    const params = this.source.params();
    if (this.disposed || !params || !this.hash || this.requested === this.hash) return;
    const hash = this.hash;
    this.requested = hash;
    this.client.request(params, this.source.volumes(), this.source.edits?.()).then(
      (lods) => {
        if (this.disposed || lods.meta.hash !== this.hash || hash !== this.hash) return;
        this.setLods(lods);
        this.wake();
      },
      (error: unknown) => {
        if (this.requested === hash) this.requested = '';
        if (error instanceof Error && error.message === SUPERSEDED) return;
        console.warn('levels of detail unavailable:', error);
        this.wake(error instanceof Error ? error : new Error(String(error)));
      },
    );
  }

  private setLods(lods: LodBuffers): void {
    this.clearLevels();
    this.lods = lods;
    this.sphere = treeSphere(lods);
    if (lods.leafTexture) {
      const t = leafTexture(lods.leafTexture);
      this.leafMap = t;
      this.owned.push(t);
    }
    this.update();
  }

  /** Builds level `l` (1, 2 or the impostor) the first time it is shown. */
  private ensureLevel(l: number): boolean {
    const lods = this.lods;
    if (!lods) return false;
    if (this.levels[l]) return true;
    if (l === IMPOSTOR_LEVEL) {
      if (!this.atlas) {
        this.scheduleBake();
        return false;
      }
      const material = impostorMaterial(this.atlas, viewerLights(), { coverage: true });
      const geometry = impostorGeometry();
      this.owned.push(material, geometry);
      const group = new Group();
      const mesh = new Mesh(geometry, material);
      mesh.frustumCulled = false;
      group.add(mesh);
      this.addLevel(l, group);
      return true;
    }
    const level = lods.levels[l];
    if (!level) return false;
    const group = new Group();
    // The viewer's materials with the level's groups (its cut faces show their end grain).
    const barkMaterial =
      this.baseMaterial('bark') ??
      this.own(new MeshStandardMaterial({ color: BARK_COLOR, roughness: 0.92 }));
    const bark = barkMesh(level, barkMaterial, lods.meta.levels[l]?.groups);
    this.owned.push(bark.geometry);
    bark.castShadow = true;
    bark.receiveShadow = true;
    group.add(bark);
    const base = this.baseMaterial('leaves');
    const leafMaterial =
      (Array.isArray(base) ? base[0] : base) ?? this.own(this.fallbackLeafMaterial());
    const leaves = leafMesh(level, leafMaterial);
    if (leaves) {
      this.owned.push(leaves.geometry, leaves);
      leaves.castShadow = true;
      leaves.receiveShadow = true;
      group.add(leaves);
    }
    const cloud = cloudGeometry(level);
    if (cloud && lods.clump) {
      const map = this.own(clumpTexture(lods.clump));
      const cloudMesh = new Mesh(cloud, this.own(cloudMaterial(map)));
      this.owned.push(cloud);
      cloudMesh.castShadow = true;
      cloudMesh.receiveShadow = true;
      group.add(cloudMesh);
    }
    this.addLevel(l, group);
    return true;
  }

  private addLevel(l: number, group: Group): void {
    group.visible = false;
    this.levels[l] = group;
    this.root.add(group);
  }

  private own<T extends { dispose(): void }>(x: T): T {
    this.owned.push(x);
    return x;
  }

  private fallbackLeafMaterial(): MeshStandardMaterial {
    const material = new MeshStandardMaterial({
      color: '#ffffff',
      map: this.leafMap,
      alphaTest: 0.5,
      side: DoubleSide,
      roughness: 0.7,
    });
    applyLeafCoverage(material);
    return material;
  }

  /**
   * The viewer's own leaf material, or its bark mesh's materials (the whole array: bark, leaves,
   * cut face), so the levels look like LOD0 (and follow it).
   */
  private baseMaterial(kind: 'bark' | 'leaves'): Material | Material[] | null {
    for (const o of this.base) {
      const m = (o as Mesh).material;
      // Pulled leaves (leafPull.ts) hand over the same look for an InstancedMesh.
      const instanced = o.userData[LEAF_INSTANCED_MATERIAL_KEY] as Material | undefined;
      if (instanced) {
        if (kind === 'leaves') return instanced;
        continue;
      }
      const isLeaves = (o as InstancedMesh).isInstancedMesh === true;
      if (kind === 'leaves' && isLeaves && m && !Array.isArray(m)) return m;
      if (kind === 'bark' && !isLeaves && (Array.isArray(m) ? m.length > 0 : m)) return m;
    }
    return null;
  }

  /** Bakes the impostor after the current frame (never inside a render call). */
  private scheduleBake(): void {
    if (this.bakeScheduled || this.atlas || !this.lods) return;
    if (!this.renderer) {
      this.host.requestRender(); // the probe captures the renderer on the next frame
      return;
    }
    this.bakeScheduled = true;
    const lods = this.lods;
    setTimeout(() => {
      this.bakeScheduled = false;
      if (this.disposed || this.lods !== lods || !this.renderer || this.atlas) return;
      this.atlas = this.bake(this.renderer, lods);
      this.owned.push(this.atlas);
      this.update();
    }, 0);
  }

  private bake(renderer: WebGLRenderer, lods: LodBuffers): ImpostorAtlas {
    const level = lods.levels[0]!;
    const bark = barkGeometry(level);
    const leafMap = this.leafMap;
    const parts = [{ geometry: bark, color: BARK_COLOR, map: null }];
    const leaves = leafGeometry(level);
    // The Season's parts are baked too: the impostor of a tree in fruit shows its fruit.
    const organs = organBakeParts(this.organs);
    const out = bakeImpostor(
      renderer,
      [
        ...parts,
        ...(leaves
          ? [
              {
                geometry: leaves,
                instances: { matrices: level.leafMatrices, colors: level.leafColors },
                color: '#ffffff',
                map: leafMap,
                doubleSided: true,
              },
            ]
          : []),
        ...organs,
      ],
      this.sphere,
      // The viewer draws shadows: the atlas keeps where the tree shadows itself.
      { frames: 8, cellPx: 160, sunDirection: viewerLights().sunDir },
    );
    bark.dispose();
    leaves?.dispose();
    organs.forEach((o) => o.geometry.dispose());
    return out;
  }

  private screenSize(): number {
    const { camera } = this.host;
    const d = camera.position.distanceTo(this.sphere.center);
    return screenFraction(this.sphere.radius, d, camera.fov);
  }

  /** Picks the level and shows it. */
  private update(): void {
    if (this.disposed) return;
    const mode = this.mode;
    const hidden = mode === 'hidden';
    const wanted =
      mode === 'auto' || mode === 'hidden' ? selectLod(this.level, this.screenSize()) : mode;
    // A coarser level is wanted now: build the levels without waiting for the idle timer.
    if (wanted > 0 && !this.lods) this.requestLods();
    // Fall back to the nearest finer level that is ready (LOD0 always is).
    let shown = wanted;
    while (shown > 0 && !this.ensureLevel(shown)) shown--;
    this.level = shown;
    this.setBaseVisible(shown === 0 && !hidden);
    for (let l = 1; l < LEVEL_COUNT; l++) {
      const group = this.levels[l];
      if (group) group.visible = l === shown && !hidden;
    }
    this.host.requestRender();
    const state = this.state();
    const last = this.last;
    if (
      !last ||
      last.level !== state.level ||
      last.mode !== state.mode ||
      last.ready !== state.ready ||
      last.bakeMs !== state.bakeMs ||
      Math.abs(last.screen - state.screen) > 0.005
    ) {
      this.last = state;
      this.onState(state);
    }
  }

  private setBaseVisible(visible: boolean): void {
    for (const o of this.base) o.visible = visible;
  }

  private clearLevels(): void {
    for (const g of this.levels) if (g) this.root.remove(g);
    this.levels = [null, null, null, null];
    for (const o of this.owned) o.dispose();
    this.owned = [];
    this.atlas = null;
    this.lods = null;
    this.leafMap = null;
  }
}
