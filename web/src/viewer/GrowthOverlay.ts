/**
 * Growth-mode overlay of the viewer: the markers as points, the volumes as wireframes (crown
 * ellipsoid or envelope bounds, the wall box, the user's primitives) and a TransformControls
 * gizmo on the selected primitive. Dragging reports edits (`onEdit`) continuously, so the app
 * regrows the tree through the latest-wins scheduler while the mouse moves.
 */
import {
  BoxGeometry,
  BufferAttribute,
  BufferGeometry,
  CylinderGeometry,
  Group,
  LineBasicMaterial,
  LineSegments,
  Points,
  PointsMaterial,
  SphereGeometry,
  WireframeGeometry,
  type Object3D,
} from 'three';
import { TransformControls } from 'three/addons/controls/TransformControls.js';
import {
  normalizeVolume,
  type Params,
  type TreeBuffers,
  type VolumeGroup,
  type VolumeKind,
  type VolumePrimitive,
} from 'sylva-trees/core';
import type { OverlayHost } from './overlayHost';

/** Wireframe colour per group (crown green, shadow grey, exclusion red); the params' crown blue. */
export const GROUP_COLORS: Record<VolumeGroup, string> = {
  crown: '#2e8b3a',
  shadow: '#555555',
  exclusion: '#c0392b',
};
const CROWN_COLOR = '#2f6fb0';
const WALL_COLOR = '#8a6d3b';
const MARKER_COLOR = '#e0a100';

/** What the overlay draws. */
export interface GrowthOverlayState {
  /** Growth mode is on (nothing is drawn otherwise). */
  growth: boolean;
  showMarkers: boolean;
  showVolumes: boolean;
  /** The current params (crown volume, start points, wall). */
  params: Params;
  volumes: readonly VolumePrimitive[];
  /** Index of the primitive carrying the gizmo, or null. */
  selected: number | null;
  /** Gizmo mode. */
  mode: 'translate' | 'scale';
}

/** Unit wireframes, scaled per primitive (shared, disposed with the overlay). */
function unitGeometry(kind: VolumeKind): BufferGeometry {
  if (kind === 'sphere') return new WireframeGeometry(new SphereGeometry(1, 16, 10));
  if (kind === 'box') return new WireframeGeometry(new BoxGeometry(1, 1, 1));
  return new WireframeGeometry(new CylinderGeometry(1, 1, 1, 20, 1));
}

/** Object scale of a primitive (unit shapes: sphere radius 1, box 1³, cylinder radius 1 height 1). */
function scaleOf(v: VolumePrimitive): [number, number, number] {
  if (v.kind === 'sphere') return [v.size[0], v.size[0], v.size[0]];
  if (v.kind === 'cylinder') return [v.size[0], v.size[1], v.size[0]];
  return v.size;
}

/** The primitive an edited object now describes (uniform scale for spheres, round cylinders). */
function volumeOf(base: VolumePrimitive, object: Object3D): VolumePrimitive {
  const p = object.position;
  const s = object.scale;
  let size: [number, number, number];
  if (base.kind === 'sphere') {
    // The gizmo may scale one axis: take the axis that changed most.
    const r = [s.x, s.y, s.z].reduce((a, b) =>
      Math.abs(b - base.size[0]) > Math.abs(a - base.size[0]) ? b : a,
    );
    size = [r, r, r];
  } else if (base.kind === 'cylinder') {
    const r = Math.abs(s.x - base.size[0]) >= Math.abs(s.z - base.size[0]) ? s.x : s.z;
    size = [r, s.y, r];
  } else {
    size = [s.x, s.y, s.z];
  }
  return normalizeVolume({ ...base, centre: [p.x, p.y, p.z], size });
}

/** See the module comment. */
export class GrowthOverlay {
  private readonly root = new Group();
  private readonly volumesGroup = new Group();
  /** The markers array drawn (the same array again needs no new geometry). */
  private shownMarkers: Float32Array | undefined = undefined;
  private readonly markers = new Points(
    new BufferGeometry(),
    new PointsMaterial({ color: MARKER_COLOR, size: 3, sizeAttenuation: false }),
  );
  private readonly units: Record<VolumeKind, BufferGeometry> = {
    sphere: unitGeometry('sphere'),
    box: unitGeometry('box'),
    cylinder: unitGeometry('cylinder'),
  };
  private readonly materials = new Map<string, LineBasicMaterial>();
  private readonly paramShapes = new Group();
  private prims: { object: LineSegments; volume: VolumePrimitive }[] = [];
  private readonly gizmo: TransformControls;
  private readonly gizmoHelper: Object3D;
  private dragging = false;
  private readonly unsubscribe: () => void;

  constructor(
    private readonly host: OverlayHost,
    /** An edit of primitive `index`; `done` is true when the drag ends. */
    private readonly onEdit: (index: number, volume: VolumePrimitive, done: boolean) => void,
  ) {
    this.markers.frustumCulled = false;
    this.markers.renderOrder = 2;
    this.root.add(this.markers, this.volumesGroup);
    this.volumesGroup.add(this.paramShapes);
    this.root.visible = false;
    host.scene.add(this.root);
    this.gizmo = new TransformControls(host.camera, host.domElement);
    this.gizmo.size = 0.8;
    this.gizmoHelper = this.gizmo.getHelper();
    host.scene.add(this.gizmoHelper);
    this.gizmo.addEventListener('dragging-changed', (event) => {
      this.dragging = Boolean(event.value);
      host.orbit.enabled = !this.dragging;
      if (!this.dragging) this.emit(true);
    });
    this.gizmo.addEventListener('objectChange', () => this.emit(false));
    this.gizmo.addEventListener('change', () => host.requestRender());
    this.unsubscribe = host.onTree((buffers) => this.setMarkers(buffers));
  }

  /** Number of markers drawn now (0 when hidden; for tests). */
  get markersShown(): number {
    if (!this.root.visible || !this.markers.visible) return 0;
    return this.markers.geometry.getAttribute('position')?.count ?? 0;
  }

  /** Number of primitive wireframes drawn now (0 when hidden; for tests). */
  get volumesShown(): number {
    return this.root.visible && this.volumesGroup.visible ? this.prims.length : 0;
  }

  /** Whether a gizmo drag is in progress. */
  get isDragging(): boolean {
    return this.dragging;
  }

  /** Updates everything drawn from the app state (objects are reused, so a drag survives). */
  update(state: GrowthOverlayState): void {
    this.root.visible = state.growth && (state.showMarkers || state.showVolumes);
    this.markers.visible = state.showMarkers;
    this.volumesGroup.visible = state.showVolumes;
    this.rebuildParamShapes(state.params);
    // Primitives: reuse objects index by index; the one being dragged keeps its transform.
    while (this.prims.length > state.volumes.length) {
      const gone = this.prims.pop();
      if (gone) this.volumesGroup.remove(gone.object);
    }
    state.volumes.forEach((volume, i) => {
      let prim = this.prims[i];
      if (!prim) {
        prim = { object: new LineSegments(this.units[volume.kind]), volume };
        this.prims.push(prim);
        this.volumesGroup.add(prim.object);
      }
      prim.object.geometry = this.units[volume.kind];
      prim.object.material = this.material(GROUP_COLORS[volume.group], i === state.selected);
      const beingDragged = this.dragging && this.gizmo.object === prim.object;
      if (!beingDragged) {
        prim.object.position.set(...volume.centre);
        prim.object.scale.set(...scaleOf(volume));
      }
      prim.volume = volume;
    });
    const target =
      state.growth && state.showVolumes && state.selected !== null
        ? this.prims[state.selected]?.object
        : undefined;
    if (target) {
      if (this.gizmo.object !== target) this.gizmo.attach(target);
      this.gizmo.setMode(state.mode);
    } else if (this.gizmo.object) {
      this.gizmo.detach();
    }
    this.host.requestRender();
  }

  /** Removes everything from the scene and frees the GPU resources. */
  dispose(): void {
    this.unsubscribe();
    this.gizmo.detach();
    this.gizmo.dispose();
    this.host.scene.remove(this.root, this.gizmoHelper);
    this.host.orbit.enabled = true;
    this.markers.geometry.dispose();
    this.markers.material.dispose();
    for (const g of Object.values(this.units)) g.dispose();
    this.disposeParamShapes();
    for (const m of this.materials.values()) m.dispose();
  }

  private emit(done: boolean): void {
    const object = this.gizmo.object;
    const index = this.prims.findIndex((p) => p.object === object);
    const prim = this.prims[index];
    if (!prim || !object) return;
    this.onEdit(index, volumeOf(prim.volume, object), done);
  }

  private setMarkers(buffers: TreeBuffers): void {
    // Session updates keep the markers array while the skeleton stays.
    if (buffers.markers !== undefined && buffers.markers === this.shownMarkers) return;
    this.shownMarkers = buffers.markers;
    const data = buffers.markers ?? new Float32Array(0);
    this.markers.geometry.dispose();
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new BufferAttribute(new Float32Array(data), 3));
    this.markers.geometry = geometry;
  }

  private material(color: string, selected: boolean): LineBasicMaterial {
    const key = `${color}${selected ? '!' : ''}`;
    let m = this.materials.get(key);
    if (!m) {
      m = new LineBasicMaterial({ color, transparent: true, opacity: selected ? 0.95 : 0.55 });
      this.materials.set(key, m);
    }
    return m;
  }

  private disposeParamShapes(): void {
    for (const child of [...this.paramShapes.children]) {
      if (child instanceof LineSegments) (child.geometry as BufferGeometry).dispose();
      this.paramShapes.remove(child);
    }
  }

  private paramKey = '';

  /** The crown (per start point) and the wall, from the params; rebuilt when they change. */
  private rebuildParamShapes(p: Params): void {
    const ids: (keyof Params)[] = [
      'crown_volume',
      'crown_base',
      'crown_height',
      'crown_radius',
      'start_points',
      'start_spacing',
      'wall',
      'wall_distance',
      'wall_height',
      'wall_width',
    ];
    const key = ids.map((id) => p[id] ?? '').join(',');
    if (key === this.paramKey) return;
    this.paramKey = key;
    this.disposeParamShapes();
    const v = (id: keyof Params, fallback: number) => p[id] ?? fallback;
    const kind = v('crown_volume', 0);
    const base = v('crown_base', 2.5);
    const height = v('crown_height', 6);
    const radius = v('crown_radius', 3.5);
    const n = Math.max(1, v('start_points', 1));
    const spacing = v('start_spacing', 2);
    // Primitives mode draws the user's crown group instead (the ellipsoid only as a fallback).
    for (let i = 0; i < n && kind !== 2; i++) {
      const crown = new LineSegments(
        kind === 1 ? unitGeometry('cylinder') : unitGeometry('sphere'),
        this.material(CROWN_COLOR, false),
      );
      crown.position.set((i - 0.5 * (n - 1)) * spacing, base + height / 2, 0);
      crown.scale.set(radius, kind === 1 ? height : height / 2, radius);
      this.paramShapes.add(crown);
    }
    if (v('wall', 0) === 1) {
      const wall = new LineSegments(unitGeometry('box'), this.material(WALL_COLOR, false));
      const h = v('wall_height', 8);
      wall.position.set(-v('wall_distance', 1.5) - 0.1, h / 2, 0);
      wall.scale.set(0.2, h, v('wall_width', 12));
      this.paramShapes.add(wall);
    }
  }
}
