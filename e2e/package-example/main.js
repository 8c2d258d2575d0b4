// A three.js app of its own with two Sylva trees in one scene: the package README's example, plus
// `window.__example` for the e2e test (tests/package.spec.ts), which installs the packed tarball
// here in a fresh folder, builds this with Vite and opens it in Chromium.
import * as THREE from 'three';
import { SylvaTree, presets } from 'sylva-trees';

const renderer = new THREE.WebGLRenderer({ antialias: true });
renderer.setSize(window.innerWidth, window.innerHeight);
document.body.appendChild(renderer.domElement);

const scene = new THREE.Scene();
scene.background = new THREE.Color('#dce6ec');
const camera = new THREE.PerspectiveCamera(40, window.innerWidth / window.innerHeight, 0.1, 500);
camera.position.set(0, 11, 50);
camera.lookAt(0, 9.5, 0);
scene.add(new THREE.HemisphereLight('#eef4ff', '#4a3f30', 1.6));
const sun = new THREE.DirectionalLight('#fff3dc', 2.5);
sun.position.set(10, 20, 8);
scene.add(sun);

const started = performance.now();
let firstTreeMs = null;
const grow = (options) =>
  SylvaTree.create(options).then((tree) => {
    firstTreeMs ??= performance.now() - started;
    return tree;
  });
// Both generate at once, each in its own worker.
const [aspen, oak] = await Promise.all([
  grow({ preset: 'quaking_aspen', seed: 7, params: { l1_branches: 40 } }),
  grow({ preset: 'black_tupelo', seed: 3 }),
]);
aspen.object.position.x = -8;
oak.object.position.x = 8;
scene.add(aspen.object, oak.object);
const bothMs = performance.now() - started;

const clock = new THREE.Clock();
renderer.setAnimationLoop(() => {
  const dt = clock.getDelta();
  aspen.update(dt);
  oak.update(dt);
  renderer.render(scene, camera);
});

/** Pixels that differ from the sky in the left and right halves of a frame drawn now. */
function treePixels() {
  renderer.render(scene, camera);
  const gl = renderer.getContext();
  const { drawingBufferWidth: w, drawingBufferHeight: h } = gl;
  const rgba = new Uint8Array(w * h * 4);
  gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, rgba);
  const sky = [0xdc, 0xe6, 0xec];
  const halves = [0, 0];
  for (let i = 0; i < w * h; i++) {
    const d = Math.abs(rgba[i * 4] - sky[0]) + Math.abs(rgba[i * 4 + 1] - sky[1]);
    if (d + Math.abs(rgba[i * 4 + 2] - sky[2]) > 30) halves[(i % w) * 2 < w ? 0 : 1]++;
  }
  return halves;
}

window.__example = {
  presets,
  /** Stops the render loop (software WebGL in the test: each frame takes long). */
  pause: () => renderer.setAnimationLoop(null),
  firstTreeMs,
  bothMs,
  stats: () => [aspen.stats, oak.stats],
  treePixels,
  set: async (values) => {
    await aspen.set(values);
    return aspen.stats.hash;
  },
  glbBytes: async () => (await oak.toGLB()).length,
  dispose: () => {
    aspen.dispose();
    oak.dispose();
    renderer.render(scene, camera);
    return { ...renderer.info.memory, children: scene.children.length };
  },
};
document.body.dataset.ready = '1';
