/**
 * `sylva-trees`: Sylva's procedural trees in your three.js scene.
 *
 * ```ts
 * import { SylvaTree, presets, params } from 'sylva-trees';
 * const tree = await SylvaTree.create({ preset: 'quaking_aspen', seed: 7 });
 * scene.add(tree.object);
 * ```
 */
export {
  SylvaTree,
  SylvaTreeError,
  params,
  presets,
  version,
  type SylvaParamId,
  type SylvaParamInfo,
  type SylvaParams,
  type SylvaPresetId,
  type SylvaTreeChange,
  type SylvaTreeOptions,
  type SylvaTreeStats,
} from './SylvaTree';
export type { Edit as SylvaEdit } from './core/edits';
export { SceneLights as SylvaLights } from './viewer/lighting';
