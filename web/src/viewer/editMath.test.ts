/** The hand-edit tools' screen to tree space math: the plane fallback and the crown outline. */
import { PerspectiveCamera, Raycaster, Vector2, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { editsProblem, quantizeEdit } from 'sylva-trees/core';
import {
  brushPoint,
  crownProfile,
  facingPlane,
  halfWidth,
  looksFromSide,
  onPlane,
  OUTLINE_SAMPLES,
  toNdc,
  trunkPlane,
} from './editMath';

/** A camera at `from` looking at `to`. */
function cameraAt(from: [number, number, number], to: [number, number, number] = [0, 4, 0]) {
  const camera = new PerspectiveCamera(40, 1, 0.1, 1000);
  camera.position.set(...from);
  camera.lookAt(new Vector3(...to));
  camera.updateMatrixWorld(true);
  return camera;
}

/** The ray under NDC `(x, y)`. */
function rayAt(camera: PerspectiveCamera, x: number, y: number) {
  const caster = new Raycaster();
  caster.setFromCamera(new Vector2(x, y), camera);
  return caster.ray;
}

describe('brush points', () => {
  it('fall on the plane through the trunk axis facing the camera when nothing is hit', () => {
    const camera = cameraAt([0, 4, 20]);
    const p = brushPoint(null, rayAt(camera, 0.3, 0.2), camera);
    expect(p).not.toBeNull();
    // Seen along -z: the plane is z = 0, and the point is right of and above the target.
    expect(p?.z).toBeCloseTo(0, 6);
    expect(p?.x).toBeGreaterThan(0.5);
    expect(p?.y).toBeGreaterThan(4);
    // From an oblique view the plane still holds the trunk axis and faces the camera.
    const oblique = cameraAt([15, 9, 15]);
    const plane = trunkPlane(oblique);
    expect(plane.distanceToPoint(new Vector3(0, 7, 0))).toBeCloseTo(0, 6);
    expect(plane.normal.y).toBeCloseTo(0, 6);
    expect(plane.normal.x).toBeCloseTo(plane.normal.z, 6);
  });

  it('take the surface hit when there is one', () => {
    const camera = cameraAt([0, 4, 20]);
    const hit = new Vector3(1, 5, 2);
    const p = brushPoint(hit, rayAt(camera, 0, 0), camera);
    expect(p?.toArray()).toEqual([1, 5, 2]);
    expect(p).not.toBe(hit);
  });

  it('looking straight down still has a vertical plane through the axis', () => {
    const camera = cameraAt([0, 30, 0.0001], [0, 0, 0]);
    const plane = trunkPlane(camera);
    expect(plane.normal.y).toBeCloseTo(0, 6);
    expect(plane.distanceToPoint(new Vector3(0, 3, 0))).toBeCloseTo(0, 6);
    expect(looksFromSide(camera)).toBe(false);
    expect(looksFromSide(cameraAt([0, 4, 20]))).toBe(true);
  });

  it('a bend target lies on the plane through the grabbed point facing the camera', () => {
    const camera = cameraAt([0, 4, 20]);
    const at = new Vector3(2, 5, 1);
    const to = onPlane(rayAt(camera, 0.1, -0.1), facingPlane(camera, at));
    expect(to).not.toBeNull();
    const depth = (v: Vector3) =>
      v.clone().sub(camera.position).dot(camera.getWorldDirection(new Vector3()));
    expect(depth(to as Vector3)).toBeCloseTo(depth(at), 5);
  });

  it('maps client pixels to normalised device coordinates', () => {
    const rect = { left: 100, top: 50, width: 400, height: 200 };
    expect(toNdc(100, 50, rect)).toEqual([-1, 1]);
    expect(toNdc(500, 250, rect)).toEqual([1, -1]);
    expect(toNdc(300, 150, rect)).toEqual([0, 0]);
  });
});

describe('crown outline', () => {
  it('becomes a simple [radius, height] profile from the axis up the outside and back', () => {
    const camera = cameraAt([0, 5, 25], [0, 5, 0]);
    // A diamond drawn around the trunk, wider on the left (x < 0) than on the right.
    const drawn = [
      new Vector3(0, 2, 0),
      new Vector3(2, 5, 0),
      new Vector3(0, 9, 0),
      new Vector3(-3, 5, 0),
    ];
    const profile = crownProfile(drawn, camera);
    expect(profile).not.toBeNull();
    const p = profile as [number, number][];
    expect(p).toHaveLength(OUTLINE_SAMPLES + 2);
    expect(p[0]).toEqual([0, 2]);
    expect(p.at(-1)).toEqual([0, 9]);
    // The widest side counts: 3 m at 5 m height.
    const widest = Math.max(...p.map(([r]) => r));
    expect(widest).toBeGreaterThan(2.8);
    expect(widest).toBeLessThanOrEqual(3);
    // Heights rise; the profile is valid for the core once on the centimetre grid.
    for (let i = 1; i < p.length; i++) expect(p[i]?.[1]).toBeGreaterThan(p[i - 1]?.[1] ?? 0);
    expect(editsProblem([quantizeEdit({ op: 'crown', outline: p })])).toBeNull();
  });

  it('a scribble that crosses itself still gives a simple outline; a dot gives none', () => {
    const camera = cameraAt([0, 5, 25], [0, 5, 0]);
    const scribble = Array.from({ length: 60 }, (_, k) => {
      const a = k * 0.9;
      return new Vector3(Math.cos(a) * (1 + k / 30), 3 + Math.sin(a * 1.7) * 2 + k / 20, 0);
    });
    const p = crownProfile(scribble, camera);
    expect(p).not.toBeNull();
    expect(editsProblem([quantizeEdit({ op: 'crown', outline: p ?? [] })])).toBeNull();
    expect(
      crownProfile(
        [new Vector3(1, 5, 0), new Vector3(1.01, 5, 0), new Vector3(1, 5.02, 0)],
        camera,
      ),
    ).toBeNull();
  });

  it('measures the half-width where an edge crosses a height', () => {
    const square: [number, number][] = [
      [-1, 0],
      [2, 0],
      [2, 4],
      [-1, 4],
    ];
    expect(halfWidth(square, 2)).toBe(2);
    expect(halfWidth(square, 5)).toBe(0);
  });
});
