/**
 * The tools' pointer handling without a browser: a stub canvas (an EventTarget), a real camera
 * and the plane fallback (nothing to hit).
 */
import { PerspectiveCamera, Scene } from 'three';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { Edit } from 'sylva-trees/core';
import { HandEditTools } from './HandEditTools';
import type { OverlayHost } from './overlayHost';

type Stub = EventTarget & { style: Record<string, string> };

function setup() {
  const canvas = Object.assign(new EventTarget(), {
    style: {},
    getBoundingClientRect: () => ({ left: 0, top: 0, width: 400, height: 400 }),
    setPointerCapture() {},
    releasePointerCapture() {},
  }) as Stub;
  const camera = new PerspectiveCamera(40, 1, 0.1, 1000);
  camera.position.set(0, 6, 30);
  camera.lookAt(0, 6, 0);
  camera.updateMatrixWorld(true);
  const host = {
    scene: new Scene(),
    camera,
    domElement: canvas as unknown as HTMLCanvasElement,
    orbit: { enabled: true },
    requestRender() {},
    pickables: () => [],
    onTree: () => () => {},
    onHash: () => () => {},
  } as unknown as OverlayHost;
  const drafts: Edit[] = [];
  const tools = new HandEditTools(host, {
    draft: (edit) => drafts.push(edit),
    commit: () => {},
    cancel: () => {},
    notice: () => {},
  });
  const fire = (type: string, x: number, y: number) =>
    canvas.dispatchEvent(
      Object.assign(new Event(type), { clientX: x, clientY: y, pointerId: 1, button: 0 }),
    );
  return { tools, drafts, fire };
}

describe('HandEditTools', () => {
  let frames: FrameRequestCallback[];
  let clock: number;
  beforeEach(() => {
    frames = [];
    clock = 1000;
    vi.stubGlobal('window', new EventTarget());
    vi.stubGlobal('performance', { now: () => clock });
    vi.stubGlobal('requestAnimationFrame', (cb: FrameRequestCallback) => frames.push(cb));
    vi.stubGlobal('cancelAnimationFrame', () => {});
  });
  afterEach(() => vi.unstubAllGlobals());

  // Regression: every move waited for the next animation frame before the stroke grew, half a
  // frame on average and a whole one at worst, added to every answer while painting.
  it('grows from the press, handles a move at once, and moves within half a frame at the next frame', () => {
    const { tools, drafts, fire } = setup();
    tools.set('paint', { radius: 0.6, density: 400, segment: 0.25, kill: 0.4 });
    fire('pointerdown', 200, 200);
    // The press starts the stroke: its first brush point grows at once.
    expect(drafts).toHaveLength(1);
    clock += 16;
    fire('pointermove', 220, 200);
    expect(drafts).toHaveLength(2);
    expect(frames).toHaveLength(0);
    // A fast pen: the next move 2 ms later waits for the frame; a newer one replaces it.
    clock += 2;
    fire('pointermove', 240, 200);
    clock += 2;
    fire('pointermove', 260, 200);
    expect(drafts).toHaveLength(2);
    expect(frames).toHaveLength(1);
    frames.shift()?.(clock);
    expect(drafts).toHaveLength(3);
    const last = drafts[2];
    expect(last?.op).toBe('paint');
    if (last?.op === 'paint') expect(last.points).toHaveLength(3);
    tools.dispose();
  });
});
