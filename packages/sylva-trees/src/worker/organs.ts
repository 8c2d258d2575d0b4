/**
 * The organ sets (flowers, fruit, catkins, buds) of the session's current tree, read out of
 * the wasm module for the tree message: one JSON call for the sets' kind, name, colour and
 * roughness, then one typed-array copy per array, which the worker transfers. Also the mean
 * tint of the leaves on the tree (the Season's leaf colour for the leaf inspector), summed here
 * in the worker so the main thread never loops over the leaves.
 */
import type { OrganKind, OrganSetBuffers, WasmSession } from '../core/types';

/** One entry of the module's `organs_json()`. */
interface OrganSetJson {
  kind: OrganKind;
  name: string;
  color: [number, number, number];
  roughness: number;
  count: number;
}

/** The current tree's organ sets ([] when the module has none or the tree carries none). */
export function organsOf(s: WasmSession): OrganSetBuffers[] {
  if (typeof s.organs_json !== 'function' || !s.organ_count || s.organ_count() === 0) return [];
  const list = JSON.parse(s.organs_json()) as OrganSetJson[];
  const arrays = s as Required<
    Pick<
      WasmSession,
      'organ_positions' | 'organ_normals' | 'organ_indices' | 'organ_matrices' | 'organ_colors'
    >
  >;
  return list.map((set, i) => ({
    kind: set.kind,
    name: set.name,
    color: set.color,
    roughness: set.roughness,
    positions: arrays.organ_positions(i),
    normals: arrays.organ_normals(i),
    indices: arrays.organ_indices(i),
    matrices: arrays.organ_matrices(i),
    colors: arrays.organ_colors(i),
  }));
}

/** Every array of `sets`, for the transfer list. */
export function organViews(sets: OrganSetBuffers[] | undefined): ArrayBufferView[] {
  return (sets ?? []).flatMap((o) => [o.positions, o.normals, o.indices, o.matrices, o.colors]);
}

/**
 * The mean RGB of the first `onTree` tints of `colors` (3 floats each): the leaves on the tree,
 * the fallen ones after them left out. Null when there is none.
 */
export function meanTint(colors: Float32Array, onTree: number): [number, number, number] | null {
  const n = Math.min(onTree, Math.floor(colors.length / 3));
  if (n <= 0) return null;
  let r = 0;
  let g = 0;
  let b = 0;
  for (let i = 0; i < n * 3; i += 3) {
    r += colors[i]!;
    g += colors[i + 1]!;
    b += colors[i + 2]!;
  }
  return [r / n, g / n, b / n];
}
