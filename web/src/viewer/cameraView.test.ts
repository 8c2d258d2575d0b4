/** The debug hooks' camera move: projecting right after it needs no frame in between. */
import { PerspectiveCamera, Scene, Vector3 } from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import { describe, expect, it } from 'vitest';
import { lookFrom } from './cameraView';
import type { OverlayHost } from './overlayHost';

function host(): OverlayHost {
  const camera = new PerspectiveCamera(40, 1, 0.1, 1000);
  camera.position.set(30, 2, 5);
  camera.updateMatrixWorld(true);
  const domElement = { style: {}, addEventListener() {}, removeEventListener() {} };
  const orbit = new OrbitControls(camera);
  orbit.domElement = domElement as unknown as HTMLCanvasElement;
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
});
