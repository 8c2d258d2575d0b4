/**
 * The forest's ecology, plain TypeScript (no three.js) so it can be tested:
 *
 * * `uniqueTrees`: the forest's K unique trees, each with its own species and seed. A tree's
 *   species is what the species map (`speciesMap`, value noise seeded by the forest seed) says at
 *   the tree's own home point (the Halton sequence over the unit square), so the species mix
 *   follows the map; its seed is a hash of the forest seed and its index.
 * * `placeForest`: where the instances stand. Dart throwing (Poisson-disc sampling with a radius
 *   per point, after Cook, *Stochastic Sampling in Computer Graphics*, 1986, section 3): each
 *   candidate point takes the species the map gives there, one of that species' unique trees
 *   (by a hash of the candidate) and a scale, and is kept only if no trunk stands closer to it
 *   than their crowns allow: `CROWN_SHARE × (r_a + r_b)`, r the crown radius times the scale.
 *   Only the trees generated so far stand in: a candidate whose species has none yet is skipped,
 *   so the forest fills in as its trees arrive, and the layout of a given set of trees does not
 *   depend on the order they arrived in.
 */
import { mulberry32 } from 'sylva-trees/core';
import type { ForestLayout } from './layout';

/** Two neighbouring crowns may overlap by this much of their radii's sum (they interlock). */
export const CROWN_SHARE = 0.7;
/** Size of one species patch of the map (m). */
export const PATCH_METRES = 60;

/** One of the forest's unique trees. */
export interface UniqueTree {
  /** Index of its species in the recipe's species list. */
  species: number;
  /** Its generation seed. */
  seed: number;
}

/** A generated tree the placement can use. */
export interface PlacedTree {
  /** Its index among the unique trees (fixes the order, whatever order trees arrive in). */
  id: number;
  species: number;
  /** Crown radius (m) at scale 1: half its widest horizontal extent. */
  crown: number;
}

/** A 32-bit hash of two integers (lowbias32 steps). */
export function hash2(a: number, b: number): number {
  let h = (Math.imul(a >>> 0, 0x9e3779b1) ^ (b >>> 0)) >>> 0;
  h ^= h >>> 16;
  h = Math.imul(h, 0x7feb352d);
  h ^= h >>> 15;
  h = Math.imul(h, 0x846ca68b);
  h ^= h >>> 16;
  return h >>> 0;
}

/** Smooth value noise in [0, 1) on a lattice of unit cells, seeded. */
export function valueNoise(seed: number): (x: number, z: number) => number {
  const at = (i: number, j: number) => hash2(hash2(seed, i), j) / 4294967296;
  const fade = (t: number) => t * t * (3 - 2 * t);
  return (x, z) => {
    const i = Math.floor(x);
    const j = Math.floor(z);
    const u = fade(x - i);
    const v = fade(z - j);
    const a = at(i, j) + (at(i + 1, j) - at(i, j)) * u;
    const b = at(i, j + 1) + (at(i + 1, j + 1) - at(i, j + 1)) * u;
    return a + (b - a) * v;
  };
}

/** The species map of a forest: species index (0..species−1) at a point (m). */
export function speciesMap(seed: number, species: number): (x: number, z: number) => number {
  const noise = valueNoise(seed);
  const n = Math.max(1, Math.floor(species));
  return (x, z) => {
    // Two octaves: patches, with ragged borders.
    const v =
      (noise(x / PATCH_METRES, z / PATCH_METRES) * 2 +
        noise((x * 4) / PATCH_METRES + 17, (z * 4) / PATCH_METRES + 31)) /
      3;
    return Math.min(n - 1, Math.floor(v * n));
  };
}

/** Halton radical inverse of `i` in base `b`. */
function halton(i: number, b: number): number {
  let f = 1;
  let r = 0;
  for (let k = i; k > 0; k = Math.floor(k / b)) {
    f /= b;
    r += f * (k % b);
  }
  return r;
}

/**
 * The `count` unique trees of a forest of `species` species (see the module docs). Every species
 * gets at least one tree when `count ≥ species`: the map decides the rest.
 */
export function uniqueTrees(count: number, species: number, seed: number): UniqueTree[] {
  const k = Math.max(0, Math.floor(count));
  const n = Math.max(1, Math.floor(species));
  const map = speciesMap(seed, n);
  // Home points over a square of 4 × 4 patches: the map's own mix.
  const side = PATCH_METRES * 4;
  const trees: UniqueTree[] = [];
  for (let i = 0; i < k; i++) {
    const s = i < n && k >= n ? i : map(halton(i + 1, 2) * side, halton(i + 1, 3) * side);
    trees.push({ species: s, seed: hash2(seed, i + 1) % 1_000_000 });
  }
  return trees;
}

/** Placement settings. */
export interface PlaceOptions {
  seed: number;
  /** Species in the map (the recipe's list). */
  species: number;
  /** Scale range `[min, max]`; default [0.8, 1.2]. */
  scale?: [number, number];
}

/** Places up to `n` trees of `trees` (see the module docs); `variety` indexes `trees`. */
export function placeForest(n: number, trees: PlacedTree[], options: PlaceOptions): ForestLayout {
  const count = Math.max(0, Math.floor(n));
  const [smin, smax] = options.scale ?? [0.8, 1.2];
  const bySpecies = new Map<number, number[]>();
  trees
    .map((t, index) => ({ t, index }))
    .sort((a, b) => a.t.id - b.t.id)
    .forEach(({ t, index }) =>
      bySpecies.set(t.species, [...(bySpecies.get(t.species) ?? []), index]),
    );
  const maxCrown = Math.max(0.1, ...trees.map((t) => t.crown)) * smax;
  const meanCrown =
    trees.length > 0 ? trees.reduce((a, t) => a + t.crown, 0) / trees.length : maxCrown;
  // A square that holds `count` crowns at about half the densest packing.
  let half = Math.sqrt((count * Math.PI * (meanCrown * CROWN_SHARE * 2) ** 2) / 0.45) / 2 + 1;
  const map = speciesMap(options.seed, options.species);
  const cell = 2 * maxCrown * CROWN_SHARE;
  const grid = new Map<number, number[]>();
  const key = (i: number, j: number) => i * 73856093 + j * 19349663;
  const px: number[] = [];
  const pz: number[] = [];
  const pr: number[] = [];
  const pv: number[] = [];
  const ps: number[] = [];
  const rand = mulberry32(options.seed);
  let tries = 0;
  const budget = count * 40 + 100;
  while (px.length < count && trees.length > 0) {
    if (tries++ > budget) {
      // The square is full for these crowns: grow it and keep throwing.
      half *= 1.2;
      tries = 0;
    }
    const x = (rand() * 2 - 1) * half;
    const z = (rand() * 2 - 1) * half;
    const pick = rand();
    const s = smin + (smax - smin) * rand();
    const candidates = bySpecies.get(map(x, z));
    if (!candidates) continue;
    const v = candidates[Math.min(candidates.length - 1, Math.floor(pick * candidates.length))]!;
    const r = trees[v]!.crown * s;
    const ci = Math.floor(x / cell);
    const cj = Math.floor(z / cell);
    let free = true;
    for (let di = -1; di <= 1 && free; di++) {
      for (let dj = -1; dj <= 1 && free; dj++) {
        for (const o of grid.get(key(ci + di, cj + dj)) ?? []) {
          if (Math.hypot(px[o]! - x, pz[o]! - z) < CROWN_SHARE * (pr[o]! + r)) {
            free = false;
            break;
          }
        }
      }
    }
    if (!free) continue;
    const id = px.length;
    px.push(x);
    pz.push(z);
    pr.push(r);
    pv.push(v);
    ps.push(s);
    const k = key(ci, cj);
    grid.set(k, [...(grid.get(k) ?? []), id]);
  }
  return layoutOf(px, pz, pv, ps, rand, half, trees.length, pr);
}

/** The placed points as a `ForestLayout` (rotation drawn per tree, matrices computed once). */
function layoutOf(
  px: number[],
  pz: number[],
  pv: number[],
  ps: number[],
  rand: () => number,
  half: number,
  varieties: number,
  pr: number[],
): ForestLayout {
  const count = px.length;
  const matrices = new Float32Array(count * 16);
  const rotation = new Float32Array(count);
  const perVariety = new Int32Array(Math.max(1, varieties));
  let minSpacing = Infinity;
  for (const r of pr) minSpacing = Math.min(minSpacing, 2 * CROWN_SHARE * r);
  for (let i = 0; i < count; i++) {
    const r = rand() * Math.PI * 2;
    const s = ps[i]!;
    rotation[i] = r;
    perVariety[pv[i]!]!++;
    const c = Math.cos(r) * s;
    const sn = Math.sin(r) * s;
    const o = i * 16;
    matrices.set([c, 0, -sn, 0, 0, s, 0, 0, sn, 0, c, 0, px[i]!, 0, pz[i]!, 1], o);
  }
  return {
    count,
    x: Float32Array.from(px),
    z: Float32Array.from(pz),
    rotation,
    scale: Float32Array.from(ps),
    variety: Uint8Array.from(pv),
    matrices,
    halfSize: half,
    minSpacing: Number.isFinite(minSpacing) ? minSpacing : 0,
    perVariety,
  };
}
