/** Puts a viewer's camera at a point looking at another (the debug hooks' `view`, close-ups). */
import type { OverlayHost } from './TreeViewer';

/** Camera at `from`, orbiting `to` (metres, Y up); lets the orbit come as close as 5 cm. */
export function lookFrom(
  host: OverlayHost,
  from: [number, number, number],
  to: [number, number, number],
): void {
  host.orbit.minDistance = Math.min(host.orbit.minDistance, 0.05);
  host.camera.position.set(...from);
  host.orbit.target.set(...to);
  host.orbit.update();
  host.requestRender();
}

/** The camera's position and orbit target (metres). */
export function cameraOf(host: OverlayHost): { position: number[]; target: number[] } {
  return { position: host.camera.position.toArray(), target: host.orbit.target.toArray() };
}
