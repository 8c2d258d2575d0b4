/**
 * Test support (debug pages only): draws the current tree's leaves twice into a small target,
 * once pulled (`leafPull.ts`, as the viewer draws them) and once as a three.js `InstancedMesh`
 * of the same arrays, under one directional light, and compares the pixels. Any slip in the
 * texture layouts, the corner indexing or the tints shows as differing pixels.
 */
import {
  AmbientLight,
  BufferAttribute,
  BufferGeometry,
  Color,
  DirectionalLight,
  DoubleSide,
  MeshLambertMaterial,
  Mesh,
  Scene,
  WebGLRenderTarget,
  type Camera,
  type Texture,
  type WebGLRenderer,
} from 'three';
import type { TreeBuffers } from 'sylva-trees/core';
import { applyLeafPull, LeafPullData, wrapInstances } from 'sylva-trees/viewer';

/** What the comparison found. */
export interface LeafPullCheck {
  /** Pixels covered by leaves in the pulled drawing. */
  covered: number;
  /** Pixels whose colour differs by more than 2 levels in a channel between the two drawings. */
  differing: number;
}

/** Renders `buffers`' leaves both ways (`size`² pixels) and compares them. */
export function checkLeafPull(
  renderer: WebGLRenderer,
  camera: Camera,
  buffers: TreeBuffers,
  map: Texture | null,
  size = 256,
): LeafPullCheck {
  const foliage = buffers.foliage;
  if (!foliage) return { covered: 0, differing: 0 };
  const scene = new Scene();
  scene.background = new Color(0, 0, 0);
  const sun = new DirectionalLight(0xffffff, 2);
  sun.position.set(1, 2, 1.5);
  scene.add(sun, new AmbientLight(0xffffff, 0.3));
  const material = (vertexColors: boolean) =>
    new MeshLambertMaterial({ map, alphaTest: 0.5, side: DoubleSide, vertexColors });

  const data = new LeafPullData();
  data.setMesh(foliage);
  data.setInstances(foliage.matrices, foliage.colors);
  const pulledMaterial = material(true);
  applyLeafPull(pulledMaterial, data.uniforms);
  const pulled = new Mesh(data.geometry, pulledMaterial);

  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(foliage.positions, 3));
  geometry.setAttribute('normal', new BufferAttribute(foliage.normals, 3));
  geometry.setAttribute('uv', new BufferAttribute(foliage.uvs, 2));
  geometry.setIndex(new BufferAttribute(foliage.indices, 1));
  const instancedMaterial = material(false);
  const instanced = wrapInstances(geometry, instancedMaterial, foliage.matrices, foliage.colors);
  for (const mesh of [pulled, instanced]) mesh.frustumCulled = false;

  const target = new WebGLRenderTarget(size, size);
  const previous = renderer.getRenderTarget();
  const draw = (mesh: Mesh): Uint8Array => {
    scene.add(mesh);
    renderer.setRenderTarget(target);
    renderer.render(scene, camera);
    const pixels = new Uint8Array(size * size * 4);
    renderer.readRenderTargetPixels(target, 0, 0, size, size, pixels);
    scene.remove(mesh);
    return pixels;
  };
  try {
    const a = draw(pulled);
    const b = draw(instanced);
    let covered = 0;
    let differing = 0;
    for (let i = 0; i < a.length; i += 4) {
      if (a[i]! + a[i + 1]! + a[i + 2]! > 0) covered++;
      for (let c = 0; c < 3; c++) {
        if (Math.abs(a[i + c]! - b[i + c]!) > 2) {
          differing++;
          break;
        }
      }
    }
    return { covered, differing };
  } finally {
    renderer.setRenderTarget(previous);
    target.dispose();
    data.dispose();
    geometry.dispose();
    instanced.dispose();
    pulledMaterial.dispose();
    instancedMaterial.dispose();
  }
}
