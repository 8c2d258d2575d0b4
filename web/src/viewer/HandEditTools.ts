/**
 * The hand-edit tools in the 3D view (pointer events: mouse, pen and touch alike), drawn over
 * the tree: **Paint** lays brush points along a drag (the tree's surface under the cursor, else
 * the plane through the trunk axis facing the camera), **Crown** draws a closed outline from the
 * side, **Cut** clicks a branch, **Bend** drags a point of a branch. A drag reports its edit so
 * far on each move, at most about once per frame (`draft`, an interactive request) and the whole edit on release
 * (`commit`, one undo step); Escape cancels it. The orbit is off while a tool drags. A ring shows
 * the brush (Paint) or the point a click would take (Cut, Bend). The math is in `editMath.ts`.
 */
import {
  BufferGeometry,
  Float32BufferAttribute,
  Line,
  LineBasicMaterial,
  Mesh,
  MeshBasicMaterial,
  Raycaster,
  RingGeometry,
  Vector2,
  Vector3,
} from 'three';
import {
  editsProblem,
  MAX_OUTLINE_POINTS,
  MAX_STROKE_POINTS,
  quantizeEdit,
  type Edit,
  type EditPoint,
} from 'sylva-trees/core';
import { brushPoint, crownProfile, facingPlane, looksFromSide, onPlane, toNdc } from './editMath';
import type { OverlayHost } from './overlayHost';

/** The tools. */
export type EditTool = 'paint' | 'crown' | 'cut' | 'bend';

/** A paint stroke's settings. */
export interface Brush {
  radius: number;
  density: number;
  segment: number;
  kill: number;
}

/** What the tools report. */
export interface EditToolEvents {
  /** The edit being drawn, so far (shown with an interactive request). */
  draft(edit: Edit): void;
  /**
   * The finished edit (recorded as one step), made by a pointer release: it is requested as a
   * drag's last step (a quick answer may come first), and the release's `pointerup` reaching the
   * window then asks for the full tree, as the release of a slider does.
   */
  commit(edit: Edit): void;
  /** The drag was cancelled (Escape, or it made no edit): show the list as it was. */
  cancel(): void;
  /** Something to tell the user (e.g. "look from the side"). */
  notice(text: string): void;
}

/** A click moves less than this (px); more is an orbit drag. */
const CLICK_SLOP = 6;
const STROKE_COLOR = '#d9480f';

/** A drag in progress. */
type Drag =
  | { tool: 'paint'; points: Vector3[] }
  | { tool: 'crown'; points: Vector3[] }
  | { tool: 'bend'; at: Vector3; to: Vector3 }
  | { tool: 'cut'; at: Vector3; x: number; y: number };

/** Shortest time between two pointer moves handled at once (ms): about half a frame. */
const MIN_STEP_MS = 8;

/** See the module comment. */
export class HandEditTools {
  private tool: EditTool | null = null;
  private brush: Brush = { radius: 0.6, density: 400, segment: 0.25, kill: 0.4 };
  private drag: Drag | null = null;
  private pointerId: number | null = null;
  /** The newest pointer position not handled yet (handled once per frame). */
  private pending: { x: number; y: number } | null = null;
  private frame = 0;
  /** When a pointer position was last handled (ms). */
  private lastStep = -Infinity;
  private readonly raycaster = new Raycaster();
  private readonly ring = new Mesh(
    new RingGeometry(0.92, 1, 48),
    new MeshBasicMaterial({
      color: STROKE_COLOR,
      transparent: true,
      opacity: 0.8,
      depthTest: false,
    }),
  );
  private readonly line = new Line(
    new BufferGeometry(),
    new LineBasicMaterial({ color: STROKE_COLOR, depthTest: false }),
  );
  private readonly listeners: [string, (event: Event) => void][];

  constructor(
    private readonly host: OverlayHost,
    private readonly events: EditToolEvents,
  ) {
    for (const object of [this.ring, this.line]) {
      object.visible = false;
      object.renderOrder = 10;
      object.frustumCulled = false;
      host.scene.add(object);
    }
    const onDown = (e: Event) => this.down(e as PointerEvent);
    const onMove = (e: Event) => this.move(e as PointerEvent);
    const onUp = (e: Event) => this.up(e as PointerEvent);
    const onLeave = () => this.hideRing();
    const onKey = (e: Event) => {
      if ((e as KeyboardEvent).key !== 'Escape' || !this.drag) return;
      // The first Esc only cancels the drag; the next one puts the tool away.
      e.stopImmediatePropagation();
      this.finish(false);
    };
    this.listeners = [
      ['pointerdown', onDown],
      ['pointermove', onMove],
      ['pointerup', onUp],
      ['pointercancel', onUp],
      ['pointerleave', onLeave],
    ];
    // Capture: the tools see a press before the orbit controls, and turn the orbit off for it.
    for (const [type, fn] of this.listeners) host.domElement.addEventListener(type, fn, true);
    window.addEventListener('keydown', onKey);
    this.listeners.push(['keydown', onKey]);
  }

  /** The active tool (null: none, the view only orbits) and the brush of the next stroke. */
  set(tool: EditTool | null, brush: Brush): void {
    if (tool !== this.tool && this.drag) this.finish(false);
    this.tool = tool;
    this.brush = { ...brush };
    this.host.domElement.style.cursor = tool ? 'crosshair' : '';
    if (!tool) this.hideRing();
  }

  /** The active tool. */
  get active(): EditTool | null {
    return this.tool;
  }

  /** Whether a drag is in progress (for tests). */
  get dragging(): boolean {
    return this.drag !== null;
  }

  /** Brush points of the paint stroke being drawn (0 without one; debug hook). */
  get strokePoints(): number {
    return this.drag?.tool === 'paint' ? this.drag.points.length : 0;
  }

  /** The bark point under client pixel `(x, y)`, or null (debug hook). */
  pick(x: number, y: number): EditPoint | null {
    const hit = this.hit(x, y, false);
    return hit ? toPoint(hit) : null;
  }

  /** The client pixel of tree-space point `p` (debug hook). */
  project(p: readonly [number, number, number]): [number, number] {
    const v = new Vector3(...p).project(this.host.camera);
    const rect = this.host.domElement.getBoundingClientRect();
    return [rect.left + ((v.x + 1) / 2) * rect.width, rect.top + ((1 - v.y) / 2) * rect.height];
  }

  /** Removes the listeners and the drawn objects. */
  dispose(): void {
    cancelAnimationFrame(this.frame);
    for (const [type, fn] of this.listeners) {
      if (type === 'keydown') window.removeEventListener(type, fn);
      else this.host.domElement.removeEventListener(type, fn, true);
    }
    this.host.orbit.enabled = true;
    this.host.domElement.style.cursor = '';
    this.host.scene.remove(this.ring, this.line);
    this.ring.geometry.dispose();
    this.ring.material.dispose();
    this.line.geometry.dispose();
    this.line.material.dispose();
  }

  /** The tree surface under client point `(x, y)` (bark; leaves too for paint), or null. */
  private hit(x: number, y: number, leaves: boolean): Vector3 | null {
    this.aim(x, y);
    const targets = this.host.pickables(leaves);
    const hits = this.raycaster.intersectObjects(targets, false);
    return hits[0]?.point.clone() ?? null;
  }

  private aim(x: number, y: number): void {
    const [nx, ny] = toNdc(x, y, this.host.domElement.getBoundingClientRect());
    this.raycaster.setFromCamera(new Vector2(nx, ny), this.host.camera);
  }

  private down(event: PointerEvent): void {
    const tool = this.tool;
    if (!tool || event.button !== 0 || this.drag) return;
    const { clientX: x, clientY: y } = event;
    if (tool === 'paint') {
      this.aim(x, y);
      const first = brushPoint(this.hit(x, y, true), this.raycaster.ray, this.host.camera);
      if (!first) return;
      this.drag = { tool, points: [first] };
    } else if (tool === 'crown') {
      if (!looksFromSide(this.host.camera)) {
        this.events.notice('Crown: look at the tree from the side to draw its outline.');
        return;
      }
      this.aim(x, y);
      const first = brushPoint(null, this.raycaster.ray, this.host.camera);
      if (!first) return;
      this.drag = { tool, points: [first] };
    } else {
      const at = this.hit(x, y, false);
      if (!at) return; // Not on a branch: the press orbits the view.
      if (tool === 'cut') {
        // A click: the orbit may still turn the view if the press becomes a drag.
        this.drag = { tool, at, x, y };
        return;
      }
      this.drag = { tool, at, to: at.clone() };
    }
    this.host.orbit.enabled = false;
    // No text selection or focus change from the drag (the orbit, now off, would prevent it).
    event.preventDefault();
    this.pointerId = event.pointerId;
    this.host.domElement.setPointerCapture?.(event.pointerId);
    this.showDrag();
    // A stroke grows from the press, as NewGrowth's does: the tree around its first brush point
    // (and the start of its growth, which samples the whole tree) is ready when the hand moves.
    if (this.drag?.tool === 'paint') {
      const edit = this.editOf(this.drag);
      if (edit) this.events.draft(edit);
    }
  }

  private move(event: PointerEvent): void {
    if (!this.tool) return;
    if (this.drag && this.pointerId !== null && event.pointerId !== this.pointerId) return;
    this.pending = { x: event.clientX, y: event.clientY };
    if (this.frame !== 0) return;
    // Browsers deliver a mouse's moves about once per frame: one is handled at once, so a
    // stroke answers without waiting for the next frame; moves closer together than
    // MIN_STEP_MS (a fast pen) wait for the next frame, and only the newest one counts.
    if (performance.now() - this.lastStep >= MIN_STEP_MS) {
      this.step();
      return;
    }
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      this.step();
    });
  }

  private up(event: PointerEvent): void {
    const drag = this.drag;
    if (!drag) return;
    if (drag.tool === 'cut') {
      const moved = Math.hypot(event.clientX - drag.x, event.clientY - drag.y);
      this.drag = null;
      if (moved <= CLICK_SLOP && event.type === 'pointerup') {
        this.events.commit(quantizeEdit({ op: 'cut', at: toPoint(drag.at) }));
      }
      return;
    }
    if (event.pointerId !== this.pointerId) return;
    // The last position counts (a quick flick may end between frames).
    this.pending = { x: event.clientX, y: event.clientY };
    this.step();
    this.finish(event.type === 'pointerup');
  }

  /** Handles the newest pointer position: the ring, or the next step of the drag. */
  private step(): void {
    this.lastStep = performance.now();
    const at = this.pending;
    this.pending = null;
    if (!at || !this.tool) return;
    const drag = this.drag;
    if (!drag || drag.tool === 'cut') {
      this.placeRing(at.x, at.y);
      return;
    }
    this.aim(at.x, at.y);
    const ray = this.raycaster.ray;
    const camera = this.host.camera;
    if (drag.tool === 'paint') {
      const p = brushPoint(this.hit(at.x, at.y, true), ray, camera);
      const last = drag.points[drag.points.length - 1];
      // Points a quarter of the brush apart: enough to follow the stroke, few enough to send.
      if (!p || (last && p.distanceTo(last) < this.brush.radius / 4)) return;
      if (drag.points.length >= MAX_STROKE_POINTS) {
        this.events.notice(
          `A stroke holds at most ${MAX_STROKE_POINTS} points: release and start another.`,
        );
        return;
      }
      drag.points.push(p);
      this.placeRingAt(p);
    } else if (drag.tool === 'crown') {
      const p = brushPoint(null, ray, camera);
      const last = drag.points[drag.points.length - 1];
      if (!p || (last && p.distanceTo(last) < 0.05) || drag.points.length >= MAX_OUTLINE_POINTS) {
        return;
      }
      drag.points.push(p);
      this.showDrag();
      return;
    } else {
      const to = onPlane(ray, facingPlane(camera, drag.at));
      if (!to) return;
      drag.to = to;
    }
    this.showDrag();
    const edit = this.editOf(drag);
    if (edit) this.events.draft(edit);
  }

  /** The edit a drag makes (null: none yet). */
  private editOf(drag: Drag): Edit | null {
    switch (drag.tool) {
      case 'paint':
        return quantizeEdit({ op: 'paint', points: drag.points.map(toPoint), ...this.brush });
      case 'crown': {
        const outline = crownProfile(drag.points, this.host.camera);
        const edit = outline ? quantizeEdit({ op: 'crown', outline }) : null;
        // A tiny outline may fold onto itself on the centimetre grid: no edit then.
        return edit && editsProblem([edit]) === null ? edit : null;
      }
      case 'bend':
        return drag.at.distanceTo(drag.to) < 0.01
          ? null
          : quantizeEdit({ op: 'bend', at: toPoint(drag.at), to: toPoint(drag.to) });
      case 'cut':
        return quantizeEdit({ op: 'cut', at: toPoint(drag.at) });
    }
  }

  /** Ends the drag: commits its edit (`keep`) or cancels it. */
  private finish(keep: boolean): void {
    const drag = this.drag;
    this.drag = null;
    if (this.pointerId !== null) this.host.domElement.releasePointerCapture?.(this.pointerId);
    this.pointerId = null;
    this.host.orbit.enabled = true;
    this.line.visible = false;
    this.host.requestRender();
    if (!drag) return;
    const edit = keep ? this.editOf(drag) : null;
    if (edit) this.events.commit(edit);
    else this.events.cancel();
  }

  /** Draws the stroke, the outline or the bend as a line. */
  private showDrag(): void {
    const drag = this.drag;
    if (!drag || drag.tool === 'cut') return;
    const points =
      drag.tool === 'bend'
        ? [drag.at, drag.to]
        : drag.tool === 'crown'
          ? [...drag.points, drag.points[0] ?? new Vector3()]
          : drag.points;
    const data = points.flatMap((p) => [p.x, p.y, p.z]);
    this.line.geometry.dispose();
    const geometry = new BufferGeometry();
    geometry.setAttribute('position', new Float32BufferAttribute(data, 3));
    this.line.geometry = geometry;
    this.line.visible = true;
    this.host.requestRender();
  }

  /** The ring under the cursor: the brush on the tree or the trunk plane; a cut's point. */
  private placeRing(x: number, y: number): void {
    const tool = this.tool;
    if (tool === 'crown' || !tool) {
      this.hideRing();
      return;
    }
    const hit = this.hit(x, y, tool === 'paint');
    const p = tool === 'paint' ? brushPoint(hit, this.raycaster.ray, this.host.camera) : hit;
    if (p) this.placeRingAt(p);
    else this.hideRing();
  }

  private placeRingAt(p: Vector3): void {
    const size = this.tool === 'paint' ? this.brush.radius : 0.08;
    this.ring.position.copy(p);
    this.ring.quaternion.copy(this.host.camera.quaternion);
    this.ring.scale.setScalar(size);
    this.ring.visible = true;
    this.host.requestRender();
  }

  private hideRing(): void {
    if (!this.ring.visible) return;
    this.ring.visible = false;
    this.host.requestRender();
  }
}

function toPoint(v: Vector3): EditPoint {
  return [v.x, v.y, v.z];
}
