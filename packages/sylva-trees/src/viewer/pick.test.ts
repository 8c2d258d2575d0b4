/**
 * Picking with a ray through the pick boxes (bark) and the instances' spheres (leaves) finds
 * exactly what three.js's brute-force `raycast` finds, without touching every triangle or
 * instance.
 */
import { describe, expect, it, vi } from 'vitest';
import {
  BufferAttribute,
  BufferGeometry,
  DoubleSide,
  Euler,
  InstancedMesh,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  PlaneGeometry,
  Quaternion,
  Raycaster,
  Vector3,
  type Intersection,
} from 'three';
import { pickBoxes, PICK_RUN } from '../core/pickBoxes';
import { loadWasm } from '../testing/realWasm';
import { harness } from '../testing/workerHarness';
import { mulberry32 as rng } from '../core/random';
import { pickBark } from './barkPick';
import { wrapInstances } from './instances';

/** A soup of `n` small triangles in a 10 m box, in index order along x (like stems). */
function soup(n: number, seed: number): BufferGeometry {
  const r = rng(seed);
  const positions = new Float32Array(n * 9);
  for (let t = 0; t < n; t++) {
    const c = [(t / n) * 10 - 5, r() * 10, r() * 4 - 2];
    for (let v = 0; v < 3; v++) {
      for (let k = 0; k < 3; k++) positions[t * 9 + v * 3 + k] = (c[k] ?? 0) + (r() - 0.5) * 0.8;
    }
  }
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(positions, 3));
  g.setIndex(
    new BufferAttribute(
      Uint32Array.from({ length: n * 3 }, (_, i) => i),
      1,
    ),
  );
  g.computeBoundingSphere();
  return g;
}

function rays(count: number, seed: number): Raycaster[] {
  const r = rng(seed);
  return Array.from({ length: count }, () => {
    const origin = new Vector3(r() * 12 - 6, r() * 12 - 1, 15);
    const target = new Vector3(r() * 10 - 5, r() * 10, r() * 4 - 2);
    return new Raycaster(origin, target.sub(origin).normalize());
  });
}

describe('bark picking through pick boxes', () => {
  it("the core's boxes of a real tree are the TypeScript function's, and the worker sends them", () => {
    const wasm = loadWasm();
    const session = new wasm.Session();
    for (const params of [{}, { seed: 7, l1_branches: 30 }]) {
      session.update(JSON.stringify(params), -1);
      const core = session.pick_boxes!();
      const ts = pickBoxes(session.positions(), session.indices());
      expect(core.length).toBe(ts.length);
      expect(Buffer.from(core.buffer).equals(Buffer.from(ts.buffer))).toBe(true);
    }
    session.free?.();
    const h = harness(wasm);
    h.handle({ type: 'generate', id: 1, params: {} });
    const bark = h.lastResult().bark!;
    expect(Array.from(bark.pick!)).toEqual(Array.from(pickBoxes(bark.positions, bark.indices)));
  });

  it('boxes hold every triangle of their run', () => {
    const g = soup(1000, 1);
    const pos = g.getAttribute('position').array as Float32Array;
    const idx = g.index!.array as Uint32Array;
    const boxes = pickBoxes(pos, idx);
    expect(boxes.length).toBe(Math.ceil(1000 / PICK_RUN) * 6);
    for (let f = 0; f < 1000; f++) {
      const j = Math.floor(f / PICK_RUN) * 6;
      for (let v = 0; v < 3; v++) {
        const p = (idx[f * 3 + v] ?? 0) * 3;
        for (let k = 0; k < 3; k++) {
          expect(pos[p + k]).toBeGreaterThanOrEqual(boxes[j + k] ?? NaN);
          expect(pos[p + k]).toBeLessThanOrEqual(boxes[j + 3 + k] ?? NaN);
        }
      }
    }
  });

  it('finds the nearest hit three.js finds, on a moved mesh, front and double sided', () => {
    for (const side of [undefined, DoubleSide]) {
      const g = soup(3000, 2);
      const material = new MeshBasicMaterial(side === undefined ? {} : { side });
      const mesh = new Mesh(g, [material]);
      g.addGroup(0, 9000, 0);
      mesh.position.set(0.5, -1, 0.25);
      mesh.setRotationFromEuler(new Euler(0.1, 0.3, 0));
      mesh.updateMatrixWorld();
      const boxes = pickBoxes(
        g.getAttribute('position').array as Float32Array,
        g.index!.array as Uint32Array,
      );
      let hits = 0;
      for (const raycaster of rays(300, 3)) {
        const brute: Intersection[] = [];
        Mesh.prototype.raycast.call(mesh, raycaster, brute);
        brute.sort((a, b) => a.distance - b.distance);
        const fast: Intersection[] = [];
        pickBark(mesh, boxes, raycaster, fast);
        expect(fast.length).toBe(brute.length > 0 ? 1 : 0);
        if (brute[0] && fast[0]) {
          hits++;
          expect(fast[0].faceIndex).toBe(brute[0].faceIndex);
          expect(fast[0].distance).toBeCloseTo(brute[0].distance, 4);
          expect(fast[0].point.distanceTo(brute[0].point)).toBeLessThan(1e-4);
          expect(fast[0].object).toBe(mesh);
        }
      }
      expect(hits).toBeGreaterThan(50);
    }
  });

  it('falls back to every triangle without boxes, or with boxes of other arrays', () => {
    const g = soup(500, 4);
    const mesh = new Mesh(g, new MeshBasicMaterial());
    mesh.updateMatrixWorld();
    const spy = vi.spyOn(Mesh.prototype, 'raycast');
    const [raycaster] = rays(1, 5);
    pickBark(mesh, null, raycaster!, []);
    pickBark(mesh, new Float32Array(6), raycaster!, []);
    expect(spy).toHaveBeenCalledTimes(2);
    spy.mockRestore();
  });
});

describe('instance picking through instance spheres', () => {
  it('finds the hits and instance ids three.js finds, without its per-instance loop', () => {
    const r = rng(6);
    const n = 2000;
    const matrices = new Float32Array(n * 16);
    const m = new Matrix4();
    for (let i = 0; i < n; i++) {
      const q = new Quaternion().setFromEuler(new Euler(r() * 6, r() * 6, r() * 6));
      const s = 0.2 + r() * 0.5;
      m.compose(new Vector3(r() * 10 - 5, r() * 10, r() * 4 - 2), q, new Vector3(s, s * 1.5, s));
      m.toArray(matrices, i * 16);
    }
    const leaf = new PlaneGeometry(1, 0.6).translate(0, 0.3, 0);
    const material = new MeshBasicMaterial({ side: DoubleSide });
    const mesh = wrapInstances(leaf, material, matrices);
    mesh.position.set(0.3, 0.2, -0.1);
    mesh.updateMatrixWorld();
    const reference = new InstancedMesh(leaf, material, n);
    reference.instanceMatrix.array.set(matrices);
    reference.position.copy(mesh.position);
    reference.updateMatrixWorld();
    const getMatrixAt = vi.spyOn(InstancedMesh.prototype, 'getMatrixAt');
    let hits = 0;
    for (const raycaster of rays(200, 7)) {
      getMatrixAt.mockClear();
      const fast = raycaster.intersectObject(mesh, false);
      const fastCalls = getMatrixAt.mock.calls.length;
      const brute = raycaster.intersectObject(reference, false);
      expect(fast.map((h) => [h.instanceId, h.distance.toFixed(5)])).toEqual(
        brute.map((h) => [h.instanceId, h.distance.toFixed(5)]),
      );
      expect(fastCalls).toBe(0);
      hits += fast.length;
    }
    expect(hits).toBeGreaterThan(50);
    getMatrixAt.mockRestore();
  });
});
