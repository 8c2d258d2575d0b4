/**
 * The text of the docs page's `sylva-trees` section: the example and the API rows. Every member
 * a row names is typed against the package's exports, so a renamed call fails the type check.
 */
import type * as Package from 'sylva-trees';

type Tree = Package.SylvaTree;

/** A member of the package the docs name: a static, an instance member or an export. */
export type Member =
  | `SylvaTree.${Extract<keyof typeof Package.SylvaTree, string>}`
  | `tree.${Extract<keyof Tree, string>}`
  | Extract<keyof typeof Package, string>;

/** The three-line use, with the calls of the API. */
export const LIBRARY_EXAMPLE = `import { SylvaTree } from 'sylva-trees';

const tree = await SylvaTree.create({ preset: 'quaking_aspen', seed: 7, params: { l1_branches: 40 } });
scene.add(tree.object);          // a THREE.Group: bark mesh + instanced leaves, wind included
tree.update(deltaSeconds);       // in your render loop: advances the wind (optional)
await tree.set({ leaves: 10 });  // regenerates in the worker (the latest call wins)
tree.stats;                      // { vertices, triangles, leaves, hash }
const glb = await tree.toGLB();  // the same bytes as the app's export and the CLI
tree.dispose();                  // frees GPU buffers, textures and the worker`;

/** One row of the API table: the call as shown, what it does, and the members it names. */
export interface ApiRow {
  call: string;
  what: string;
  members: Member[];
}

/** The API table. */
export const LIBRARY_API: ApiRow[] = [
  {
    call: 'SylvaTree.create({ preset?, seed?, params?, edits?, worker? })',
    what: "a new tree: the defaults, then the preset, the seed and the values, shaped by the hand edits (the studio's sylva-edits.json). Invalid values reject with the same message as the app and the CLI; worker: false generates on the calling thread.",
    members: ['SylvaTree.create'],
  },
  {
    call: "SylvaTree.fromShareLink('v=1&seed=7&levels=2')",
    what: "the tree of one of the app's share links (a whole URL or its query), decoded as the app does.",
    members: ['SylvaTree.fromShareLink'],
  },
  {
    call: 'tree.object',
    what: 'a THREE.Group in metres, Y up, base at the origin: move, scale and add it like any object.',
    members: ['tree.object'],
  },
  {
    call: 'tree.update(dt), tree.setWind({...})',
    what: 'advances or changes the wind.',
    members: ['tree.update', 'tree.setWind'],
  },
  {
    call: 'tree.set({ id: value }), tree.set({ edits }), tree.edits',
    what: 'regenerates in the worker, rerunning only the stages the values touch; edits replaces the hand edit list (tree.edits).',
    members: ['tree.set', 'tree.edits'],
  },
  {
    call: 'tree.stats, tree.params',
    what: 'the counts and the content hash, and every parameter value.',
    members: ['tree.stats', 'tree.params'],
  },
  {
    call: "tree.toGLB({ leaves: 'baked' })",
    what: 'binary glTF; baked leaves (one mesh) for Blender and other editors.',
    members: ['tree.toGLB'],
  },
  {
    call: 'tree.dispose()',
    what: 'removes the group and frees its geometries, materials, textures and workers.',
    members: ['tree.dispose'],
  },
  {
    call: 'presets, params, SylvaLights',
    what: "the preset names, the parameter registry of this page, and the app's sky light and sun.",
    members: ['presets', 'params', 'SylvaLights'],
  },
];
