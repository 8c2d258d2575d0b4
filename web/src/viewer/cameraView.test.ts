/**
 * The debug hooks' and close-ups' camera move: projecting right after it needs no frame in
 * between, and a close-up pulls the near plane in so nothing is clipped.
 */
import { PerspectiveCamera, Scene, Vector3 } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { describe, expect, it } from 'vitest';
import { lookFrom } from './cameraView';
import type { OverlayHost } from './overlayHost';

function host(near = 0.1): OverlayHost {
  const camera = new PerspectiveCamera(45, 1, near, 600);
  camera.position.set(30, 2, 5);
  camera.updateMatrixWorld(true);
  const domElement = { style: {}, addEventListener() {}, removeEventListener() {} };
  const orbit = new OrbitControls(camera);
  orbit.domElement = domElement as unknown as HTMLCanvasElement;
  orbit.minDistance = 3;
  return {
    scene: new Scene(),
    camera,
    domElement: domElement as unknown as HTMLCanvasElement,
    orbit,
    requestRender() {},
    pickables: () => [],
    onTree: () => () => {},
    onHash: () => () => {},
  };
}

describe('lookFrom', () => {
  // Regression: a paused viewer draws no frame, and the camera's world matrices stayed where
  // the last frame left them: points projected off the canvas after the move.
  it('brings the world matrices up to date: the target projects to the centre at once', () => {
    const h = host();
    lookFrom(h, [0, 6, 20], [0, 6, 0]);
    const p = new Vector3(0, 6, 0).project(h.camera);
    expect(Math.abs(p.x)).toBeLessThan(1e-6);
    expect(Math.abs(p.y)).toBeLessThan(1e-6);
    const side = new Vector3(2, 6, 0).project(h.camera);
    expect(side.x).toBeGreaterThan(0);
  });

  it('pulls the near plane in to a tenth of the distance for a close-up', () => {
    const h = host(0.31);
    lookFrom(h, [0, 6, 0.2], [0, 6, 0]);
    expect(h.camera.near).toBeCloseTo(0.02, 6);
    expect(h.orbit.minDistance).toBe(0.05);
    expect(h.camera.position.toArray()).toEqual([0, 6, 0.2]);
    expect(h.camera.projectionMatrix.elements[10]).toBeCloseTo(-(600 + 0.02) / (600 - 0.02), 6);
  });

  it('keeps a near plane that is already close enough', () => {
    const h = host(0.05);
    lookFrom(h, [0, 0, 30], [0, 0, 0]);
    expect(h.camera.near).toBe(0.05);
  });
});
