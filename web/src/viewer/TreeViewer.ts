/** The three.js scene: renderer, orbit camera, lights, ground and the tree mesh (render on demand). */
import { fitToContainer } from './cameraView';
import type { OverlayHost } from './overlayHost';
import {
  Color,
  Fog,
  InstancedMesh,
  LineBasicMaterial,
  LineSegments,
  Mesh,
  MeshLambertMaterial,
  type Object3D,
  CircleGeometry,
  PCFShadowMap,
  PerspectiveCamera,
  Scene,
  Sphere,
  Vector3,
  WebGLRenderer,
} from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { TreeBuffers, TreeUpdate } from 'sylva-trees/core';
import {
  applySoftShadows,
  buildEnvelopeGeometry,
  ORGAN_MESH_PREFIX,
  SceneLights,
  TreeObject,
  type WindController,
} from 'sylva-trees/viewer';
import { antialiasFor, firstTreePixelRatio, webglRendererName } from './renderQuality';
import { hashPixels } from './windDebug';
import { checkLeafPull, type LeafPullCheck } from './leafPullCheck';
import { monthTint } from '../leaf/monthTint';

/** The organ meshes and fallen leaves of the tree shown ([`TreeViewer.organs`], the debug hook). */
export interface OrganDebug {
  sets: {
    name: string;
    kind: string;
    count: number;
    visible: boolean;
    /** Tree-space positions of up to 64 of its instances. */
    samples: [number, number, number][];
  }[];
  /** Leaf instances (on the tree and fallen). */
  leaves: number;
  /** Leaf instances lying on the ground (below 0.3 m). */
  onGround: number;
}

/** Scene background (also used by the e2e test to tell the tree from the sky). */
export const BACKGROUND_COLOR = '#dce6ec';
const GROUND_COLOR = '#b9b3a5';
const VIEW_DIRECTION = new Vector3(0.75, 0.32, 1).normalize();
/** Time after which the scene is drawn even without a tree (ms). */
const EMPTY_SCENE_DELAY_MS = 3000;

/** Owns every three.js object of the viewer; mesh data lives here, never in React state. */
export class TreeViewer {
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly camera = new PerspectiveCamera(40, 1, 0.05, 1000);
  private readonly controls: OrbitControls;
  private readonly lights: SceneLights;
  private readonly ground: Mesh<CircleGeometry, MeshLambertMaterial>;
  private readonly fog = new Fog(BACKGROUND_COLOR, 10, 40);
  /** Camera distance of the last framing (m): the fog starts no nearer than its multiple. */
  private frameDistance = 0;
  /** Radius of the ground disc for the tree (m): twelve of the tree's bounding radius. */
  private groundRadius = 1;
  /** The tree's meshes, materials and wind (shared with the `sylva-trees` package). */
  private readonly tree = new TreeObject(() => this.requestRender());
  private readonly envelope = new LineSegments(
    undefined,
    new LineBasicMaterial({ color: '#2f6fb0', transparent: true, opacity: 0.45 }),
  );
  private readonly resizeObserver: ResizeObserver;
  /** Wind animation: shared uniforms, clock and settings (see wind.ts). */
  readonly wind: WindController = this.tree.wind;
  private frameRequested = false;
  /**
   * Benchmarks only: no frame is drawn while false (trees still arrive and are set up), so a
   * software-WebGL frame of seconds does not sit between the steps of a timed drag.
   */
  rendering = true;
  /** Called with every new tree (the growth overlay reads its markers). */
  private readonly treeListeners = new Set<(buffers: TreeBuffers) => void>();
  private readonly hashListeners = new Set<(hash: string) => void>();
  private frameId = 0;
  private disposed = false;
  /** True until the first tree has been drawn (see [`TreeViewer.draw`]). */
  private shadowsDeferred = true;
  /** The pixel ratio to go back to after the first tree's frame (see [`TreeViewer.draw`]). */
  private restorePixelRatio: number | null = null;
  /** Whether the scene is drawn without a tree (after [`EMPTY_SCENE_DELAY_MS`]). */
  private drawEmpty = false;
  private readonly emptyTimer: ReturnType<typeof setTimeout>;

  constructor(
    private readonly container: HTMLElement,
    /** `alpha`: a canvas that can be transparent (the embed's `bg=transparent`). */
    options: { alpha?: boolean } = {},
  ) {
    // No MSAA in software WebGL, where it doubles a frame's time (renderQuality.ts).
    const antialias = antialiasFor(location.search, webglRendererName());
    this.renderer = new WebGLRenderer({ antialias, alpha: options.alpha ?? false });
    this.renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
    // Checking every shader program's link status right after it is created makes the page
    // wait for the GPU to compile it (seconds in software WebGL); production builds skip it.
    this.renderer.debug.checkShaderErrors = import.meta.env.DEV;
    this.renderer.shadowMap.enabled = true;
    this.renderer.shadowMap.type = PCFShadowMap;
    this.renderer.domElement.dataset.testid = 'viewer-canvas';
    // Until the first tree, frames only clear to the sky (see requestRender).
    this.renderer.setClearColor(BACKGROUND_COLOR, options.alpha ? 0 : 1);
    container.appendChild(this.renderer.domElement);

    this.scene.background = new Color(BACKGROUND_COLOR);
    this.scene.fog = this.fog;
    // Sky light, sun and soft shadows: one definition for every scene (lighting.ts).
    this.lights = new SceneLights(this.scene, this.renderer, { shadows: true });

    this.ground = new Mesh(
      new CircleGeometry(1, 96),
      // Lambert: the ground fills most of the view; the sky's image-based light is for the tree.
      new MeshLambertMaterial({ color: GROUND_COLOR }),
    );
    applySoftShadows(this.ground.material);
    this.ground.rotation.x = -Math.PI / 2;
    this.ground.receiveShadow = true;
    this.scene.add(this.ground);

    this.envelope.visible = false;
    this.envelope.frustumCulled = false;
    this.scene.add(this.envelope);

    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.maxPolarAngle = Math.PI * 0.495;
    this.controls.addEventListener('change', () => this.requestRender());
    this.frameBounds(new Sphere(new Vector3(0, 4, 0), 5));

    this.scene.add(this.tree.group);

    // A generator that never answers (or fails) still gets its sky and ground drawn.
    this.emptyTimer = setTimeout(() => {
      this.drawEmpty = true;
      this.requestRender();
    }, EMPTY_SCENE_DELAY_MS);

    this.resizeObserver = new ResizeObserver(() => this.resize());
    this.resizeObserver.observe(container);
    this.resize();
  }

  /** Shows a whole new tree (every array given); optionally re-frames the camera. */
  setTree(buffers: TreeBuffers, frame: boolean): void {
    this.tree.setTree(buffers);
    this.afterTree(buffers, true, frame);
  }

  /**
   * Applies a session update (only the arrays that changed): same-size arrays are swapped
   * into the existing attributes in place, other sizes get new geometry and the old is
   * disposed. Optionally re-frames the camera. Returns the whole current tree.
   */
  apply(update: TreeUpdate, frame: boolean): TreeBuffers {
    const buffers = this.tree.apply(update);
    this.afterTree(buffers, update.envelope !== undefined, frame);
    return buffers;
  }

  private afterTree(buffers: TreeBuffers, newEnvelope: boolean, frame: boolean): void {
    // The leaf inspector tints its drawing by the Season's colour of this tree's leaves.
    monthTint.set(buffers.leafTint ?? null);
    if (newEnvelope) {
      this.envelope.geometry.dispose();
      this.envelope.geometry = buildEnvelopeGeometry(buffers.envelope);
    }
    for (const listener of this.treeListeners) listener(buffers);
    const sphere = this.tree.boundingSphere;
    this.fitStage(sphere);
    if (frame) this.frameBounds(sphere);
    this.requestRender();
  }

  /** The content hash of the current tree arrived (it follows the buffers). */
  setHash(hash: string): void {
    this.tree.setHash(hash);
    for (const listener of this.hashListeners) listener(hash);
  }

  /**
   * What an overlay (the growth editor) needs: the scene, camera, canvas and orbit controls, a
   * render request, and a subscription to new trees (returns the unsubscribe function).
   */
  overlayHost(): OverlayHost {
    return {
      scene: this.scene,
      camera: this.camera,
      domElement: this.renderer.domElement,
      orbit: this.controls,
      requestRender: () => this.requestRender(),
      pickables: (leaves) => this.pickables(leaves),
      onTree: (listener) => {
        this.treeListeners.add(listener);
        return () => this.treeListeners.delete(listener);
      },
      onHash: (listener) => {
        this.hashListeners.add(listener);
        return () => this.hashListeners.delete(listener);
      },
    };
  }

  /**
   * The bark mesh and, with `leaves`, the leaves when they are an `InstancedMesh` (pulled
   * leaves are placed by their shader: a ray cannot hit them on the CPU).
   */
  private pickables(leaves: boolean): Object3D[] {
    const bark = this.tree.barkMesh;
    const out: Object3D[] = bark ? [bark] : [];
    if (leaves) {
      this.tree.group.traverse((o) => {
        if (o instanceof InstancedMesh && o.visible) out.push(o);
      });
    }
    return out;
  }

  /**
   * Sky colour (CSS colour), or null for none: a transparent canvas (with `alpha`) without the
   * ground disc and fog, for embedding over a page (embed page, `<sylva-tree>`).
   */
  setBackground(color: string | null): void {
    this.scene.background = color === null ? null : new Color(color);
    if (color !== null) this.fog.color.set(color);
    this.scene.fog = color === null ? null : this.fog;
    this.ground.visible = color !== null;
    this.renderer.setClearColor(color ?? BACKGROUND_COLOR, color === null ? 0 : 1);
    this.requestRender();
  }

  /** Shows or hides the ground disc (tests: the tree against the sky, without its shadow). */
  setGroundVisible(visible: boolean): void {
    this.ground.visible = visible;
    this.requestRender();
  }

  /** Shows or hides the crown envelope wireframe (the Show Preview parameter). */
  setPreviewVisible(visible: boolean): void {
    if (this.envelope.visible === visible) return;
    this.envelope.visible = visible;
    this.requestRender();
  }

  /** Whether the envelope wireframe is shown and has lines (for tests). */
  get previewShown(): boolean {
    return (
      this.envelope.visible && (this.envelope.geometry.getAttribute('position')?.count ?? 0) > 0
    );
  }

  /** Number of leaves drawn (for tests). */
  get leafCount(): number {
    return this.tree.leafCount;
  }

  /** Geometries alive on the GPU (`renderer.info.memory.geometries`; debug hook, leak tests). */
  get gpuGeometries(): number {
    return this.renderer.info.memory.geometries;
  }

  /** Shader programs compiled so far (three.js `renderer.info.programs`), for jank tests. */
  get gpuPrograms(): number {
    return this.renderer.info.programs?.length ?? 0;
  }

  /** Points the camera at the current tree's bounds. */
  frame(): void {
    if (this.tree.barkMesh) this.frameBounds(this.tree.boundingSphere);
  }

  /** Releases every GPU resource and removes the canvas. */
  dispose(): void {
    this.disposed = true;
    clearTimeout(this.emptyTimer);
    this.resizeObserver.disconnect();
    this.controls.dispose();
    this.tree.dispose();
    this.envelope.geometry.dispose();
    this.envelope.material.dispose();
    this.lights.dispose();
    this.ground.geometry.dispose();
    this.ground.material.dispose();
    this.renderer.dispose();
    this.renderer.domElement.remove();
  }

  /** Sizes the ground disc and the sun's shadow frustum to the tree. */
  private fitStage(sphere: Sphere): void {
    const r = Math.max(sphere.radius, 0.01);
    this.groundRadius = r * 12;
    this.ground.scale.setScalar(this.groundRadius);
    this.lights.fit(sphere);
  }

  /**
   * The ground fades into the sky instead of ending in a hard horizon: the fog starts beyond
   * the framed tree, and recedes when the view is farther out than its framing (zoomed out, or
   * a young tree seen from its mature tree's camera), so the tree itself never fades; the ground
   * disc grows past the fog.
   */
  private fitFog(): void {
    const d = Math.max(this.frameDistance, this.camera.position.distanceTo(this.controls.target));
    this.fog.near = d * 1.6;
    this.fog.far = d * 4;
    // The ground reaches past the fog: its edge never shows.
    this.ground.scale.setScalar(Math.max(this.groundRadius, d * 5));
  }

  /** Places the camera so the bounding sphere fills the view. */
  private frameBounds(sphere: Sphere): void {
    const r = Math.max(sphere.radius, 0.01);
    const vFov = (this.camera.fov * Math.PI) / 180;
    const hFov = 2 * Math.atan(Math.tan(vFov / 2) * this.camera.aspect);
    const distance = (r / Math.sin(Math.min(vFov, hFov) / 2)) * 1.05;
    this.camera.position.copy(sphere.center).addScaledVector(VIEW_DIRECTION, distance);
    this.camera.near = distance / 100;
    this.camera.far = distance * 20;
    this.frameDistance = distance;
    this.fitFog();
    this.camera.updateProjectionMatrix();
    this.controls.target.copy(sphere.center);
    this.controls.minDistance = r * 0.2;
    this.controls.maxDistance = distance * 6;
    this.controls.update();
    this.requestRender();
  }

  private resize(): void {
    fitToContainer(this.renderer, this.camera, this.container);
    this.requestRender();
  }

  /** Renders immediately (uploading any new geometry to the GPU), replacing a pending frame. */
  renderNow(): void {
    if (this.frameRequested) cancelAnimationFrame(this.frameId);
    this.frameRequested = false;
    if (!this.disposed) this.draw();
    if (this.wind.animating) this.requestRender();
  }

  /**
   * Renders now at the current wind time and hashes the canvas pixels (debug hook: a test
   * renders given frames and compares them).
   */
  frameHash(): string {
    this.renderNow();
    return hashPixels(this.renderer.getContext());
  }

  /** Size of the bark colour map, null before the worker sent it (debug hook). */
  get barkTexture(): { width: number; height: number } | null {
    return this.tree.barkTexture;
  }

  /** The bark type of the cut faces' end grain, -1 before the worker sent one (debug hook). */
  get endGrainKind(): number {
    return this.tree.endGrainKind;
  }

  private requestRender(): void {
    if (this.frameRequested || !this.rendering) return;
    if (this.tree.barkMesh === null && !this.drawEmpty) {
      // No tree yet: the canvas is only cleared to the sky colour. Drawing the empty scene
      // would make the GPU compile the ground's programs and draw it (half a second of
      // software WebGL) just when the first tree arrives.
      this.renderer.clear();
      return;
    }
    this.frameRequested = true;
    this.frameId = requestAnimationFrame((now) => {
      this.frameRequested = false;
      if (this.disposed) return;
      // While the wind blows, every frame advances its clock and asks for the next one.
      this.wind.tick(now);
      this.draw();
      if (this.wind.animating) this.requestRender();
    });
  }

  /**
   * Draws a frame. The page's first tree is drawn once without casting shadows, and the next
   * frame adds them: the shadow pass and its two depth programs cost about 0.6 s of software
   * WebGL (SwiftShader), so the tree appears that much sooner; on a GPU the shadows follow one
   * frame later. The shadow map is still rendered (empty), so no shader program changes. In
   * software WebGL that first frame is also drawn at half the resolution, and the next one
   * sharp ([`firstTreePixelRatio`]).
   */
  private draw(): void {
    if (this.restorePixelRatio !== null) {
      this.renderer.setPixelRatio(this.restorePixelRatio);
      this.restorePixelRatio = null;
    }
    const defer = this.shadowsDeferred && this.tree.barkMesh !== null;
    const casting: Object3D[] = [];
    if (defer) {
      this.tree.group.traverse((object) => {
        if (object.castShadow) casting.push(object);
        object.castShadow = false;
      });
      const ratio = this.renderer.getPixelRatio();
      const first = firstTreePixelRatio(ratio, webglRendererName());
      if (first !== ratio) {
        this.restorePixelRatio = ratio;
        this.renderer.setPixelRatio(first);
      }
    }
    this.fitFog();
    this.renderer.render(this.scene, this.camera);
    if (defer) {
      for (const object of casting) object.castShadow = true;
      this.shadowsDeferred = false;
      this.requestRender();
    }
  }

  /**
   * Test support: the organ meshes in the scene (name, kind, instances, shown) and how many leaf
   * instances lie on the ground (below 0.3 m: the fallen leaves) of how many.
   */
  organs(): OrganDebug {
    const sets = this.tree.organMeshes.map((m) => {
      const a = m.instanceMatrix.array;
      // Up to 64 instance positions, spread over the set (close-up screenshots aim at one).
      const step = Math.max(1, Math.ceil(m.count / 64));
      const samples: [number, number, number][] = [];
      for (let i = 0; i < m.count; i += step) {
        samples.push([a[i * 16 + 12]!, a[i * 16 + 13]!, a[i * 16 + 14]!]);
      }
      return {
        name: m.name.slice(ORGAN_MESH_PREFIX.length),
        kind: String(m.userData.organKind),
        count: m.count,
        visible: m.visible && m.parent !== null,
        samples,
      };
    });
    const matrices = this.tree.buffers?.foliage?.matrices ?? new Float32Array(0);
    let onGround = 0;
    for (let i = 13; i < matrices.length; i += 16) if (matrices[i]! < 0.3) onGround++;
    return { sets, leaves: matrices.length / 16, onGround };
  }

  /** Test support: shows or hides the organ meshes (a frame with and without them). */
  setOrgansVisible(visible: boolean): void {
    for (const m of this.tree.organMeshes) m.visible = visible;
    this.requestRender();
  }

  /** Test support: the current leaves drawn pulled and instanced, compared (leafPullCheck.ts). */
  leafPullCheck(): LeafPullCheck | null {
    const buffers = this.tree.buffers;
    if (!buffers) return null;
    return checkLeafPull(this.renderer, this.camera, buffers, this.tree.leafMap);
  }

  /**
   * Renders a frame now and waits for it to be drawn (a one-pixel read-back); returns the time
   * it took (ms): the upload of new buffers and the draw. For benchmarks.
   */
  probeFrame(): number {
    const t0 = performance.now();
    this.renderer.render(this.scene, this.camera);
    const gl = this.renderer.getContext();
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
    return performance.now() - t0;
  }
}
