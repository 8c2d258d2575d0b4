/**
 * What the viewer lends its overlays (the growth-volume editor, the LOD preview, the camera
 * helpers): its scene, camera, canvas and orbit, a way to ask for a frame, and the tree's buffers
 * and hash as they arrive. `TreeViewer.overlayHost()` hands one out.
 */
import type { PerspectiveCamera, Scene } from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { TreeBuffers } from 'sylva-trees/core';

/** See [`TreeViewer.overlayHost`]. */
export interface OverlayHost {
  scene: Scene;
  camera: PerspectiveCamera;
  domElement: HTMLCanvasElement;
  orbit: OrbitControls;
  requestRender(): void;
  onTree(listener: (buffers: TreeBuffers) => void): () => void;
  /** Subscribes to the current tree's content hash, which arrives after its buffers. */
  onHash(listener: (hash: string) => void): () => void;
}
