// sylva-trees without a bundler: a plain module script and an import map (index.html). One tree
// in the page's own scene, framed from its bounding box; the test reads the result from
// window.__importMap and the canvas.
import * as THREE from 'three';
import { SylvaTree, presets } from 'sylva-trees';

const renderer = new THREE.WebGLRenderer({ antialias: false, preserveDrawingBuffer: true });
renderer.setSize(480, 320);
document.body.appendChild(renderer.domElement);
const scene = new THREE.Scene();
scene.background = new THREE.Color('#ffffff');
scene.add(new THREE.HemisphereLight('#ffffff', '#555555', 2.5));
const camera = new THREE.PerspectiveCamera(40, 480 / 320, 0.1, 500);

try {
  const tree = await SylvaTree.create({ preset: 'quaking_aspen', seed: 7, params: { levels: 2 } });
  scene.add(tree.object);
  const box = new THREE.Box3().setFromObject(tree.object);
  const centre = box.getCenter(new THREE.Vector3());
  const size = box.getSize(new THREE.Vector3()).length();
  camera.position.set(centre.x, centre.y, centre.z + size * 1.3);
  camera.lookAt(centre);
  renderer.render(scene, camera);
  window.__importMap = { stats: tree.stats, presets: presets.length };
} catch (e) {
  window.__importMap = { error: e instanceof Error ? e.message : String(e) };
}
document.body.dataset.ready = '1';
