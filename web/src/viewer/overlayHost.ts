/**
 * What the viewer lends its overlays (the growth-volume editor, the hand-edit tools, the LOD
 * preview, the camera helpers): its scene, camera, canvas and orbit, a way to ask for a frame,
 * the tree's objects to pick, and the tree's buffers and hash as they arrive. `TreeViewer.overlayHost()` hands one out.
 */
import type { Object3D, PerspectiveCamera, Scene } from 'three';
import type { OrbitControls } from 'three/addons/controls/OrbitControls.js';
import type { TreeBuffers } from 'sylva-trees/core';

/** See [`TreeViewer.overlayHost`]. */
export interface OverlayHost {
  scene: Scene;
  camera: PerspectiveCamera;
  domElement: HTMLCanvasElement;
  orbit: OrbitControls;
  requestRender(): void;
  /** The tree's objects a pointer may hit: the bark, and with `leaves` the instanced leaves. */
  pickables(leaves: boolean): Object3D[];
  onTree(listener: (buffers: TreeBuffers) => void): () => void;
  /** Subscribes to the current tree's content hash, which arrives after its buffers. */
  onHash(listener: (hash: string) => void): () => void;
}
