/** The close-up camera: comes as close as asked, the near plane pulled in so nothing is clipped. */
import { PerspectiveCamera, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { lookFrom } from './cameraView';
import type { OverlayHost } from './overlayHost';

function host(near: number): OverlayHost {
  const camera = new PerspectiveCamera(45, 1, near, 600);
  const orbit = { minDistance: 3, target: new Vector3(), update: () => undefined };
  return { camera, orbit, requestRender: () => undefined } as unknown as OverlayHost;
}

describe('lookFrom', () => {
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
