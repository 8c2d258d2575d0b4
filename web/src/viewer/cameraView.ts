/**
 * Camera helpers: a viewer's camera put at a point looking at another (the debug hooks' `view`,
 * close-ups), and a canvas and camera fitted to their container.
 */
import type { PerspectiveCamera, WebGLRenderer } from 'three';
import type { OverlayHost } from './overlayHost';

/**
 * Camera at `from`, orbiting `to` (metres, Y up); lets the orbit come as close as 5 cm, and pulls
 * the near plane in to a tenth of the distance when it lies farther (the tree's framing puts it at
 * a hundredth of a whole-tree view, 31 cm for the default tree, which clipped a close-up).
 */
export function lookFrom(
  host: OverlayHost,
  from: [number, number, number],
  to: [number, number, number],
): void {
  host.orbit.minDistance = Math.min(host.orbit.minDistance, 0.05);
  const distance = Math.hypot(from[0] - to[0], from[1] - to[1], from[2] - to[2]);
  if (distance > 0 && host.camera.near > distance / 10) {
    host.camera.near = distance / 10;
    host.camera.updateProjectionMatrix();
  }
  host.camera.position.set(...from);
  host.orbit.target.set(...to);
  host.orbit.update();
  // Picking and projecting read the camera's world matrices, which a frame updates: a paused
  // viewer (a benchmark) draws none, so bring them up to date now.
  host.camera.updateMatrixWorld();
  host.requestRender();
}

/** The camera's position and orbit target (metres). */
export function cameraOf(host: OverlayHost): { position: number[]; target: number[] } {
  return { position: host.camera.position.toArray(), target: host.orbit.target.toArray() };
}

/** Sizes the canvas to `container` (at least 1 px) and the camera's aspect to match. */
export function fitToContainer(
  renderer: WebGLRenderer,
  camera: PerspectiveCamera,
  container: HTMLElement,
): void {
  const width = Math.max(container.clientWidth, 1);
  const height = Math.max(container.clientHeight, 1);
  renderer.setSize(width, height, true);
  camera.aspect = width / height;
  camera.updateProjectionMatrix();
}
