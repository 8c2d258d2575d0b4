// Gallery sections: every broadleaf preset through the year (Season: spring, July, its species'
// autumn peak, bare January), one row each, seen from the same camera as July; then close-ups of
// blossom, fruit, catkins, buds and fallen leaves, the camera placed by the native CLI's
// `--report foliage` (the instances' origins).
import { imageTable } from './context.mjs';

/** Each leaf calendar's (Phenology's index) autumn peak: mid-October to early November. */
const AUTUMN = {
  0: 10.3, // aspen
  1: 10.5, // maple
  2: 11, // oak
  3: 10.4, // birch
  4: 11, // ginkgo
  5: 10.9, // willow
  6: 10.1, // tupelo
  8: 10.5, // cherry
  9: 10.9, // apple
};
/** Spring: late April's flush, or the blossom of the flowering species. */
const SPRING = { 8: 4.2, 9: 4.9 };
/** Evergreen Conifer: not in the strip. */
const CONIFER = 7;

/** The presets the strip shows: every broadleaf one, with its calendar's index. */
export function broadleaves(presets) {
  return presets
    .map((p) => ({ p, kind: p.values.leaf_phenology ?? 0 }))
    .filter(({ kind }) => kind !== CONIFER);
}

export const seasonsSection = {
  id: 'seasons',
  title: 'Seasons',
  intro:
    "The Season slider on every broadleaf preset: spring (late April's flush; the cherry's and the apple's blossom), July, autumn at the species' peak (mid-October to early November; sun leaves outside the crown first) and January (bare, with buds at the shoot tips and last autumn's leaves on the ground). Each row keeps July's camera.",
  layout: (shots) => imageTable(shots, 4),
  async shots(ctx) {
    const shots = [];
    for (const { p, kind } of broadleaves(ctx.presets)) {
      if (ctx.presetFilter && !ctx.presetFilter.includes(p.name)) continue;
      const spring = SPRING[kind] ?? 4.8;
      const months = [
        ['april', spring === 4.8 ? 'late April' : 'blossom', spring],
        ['july', 'July', 7],
        ['autumn', 'autumn', AUTUMN[kind] ?? 10.5],
        ['january', 'January', 1.5],
      ];
      const cam = await ctx.open(p.values);
      for (const [id, label, season] of months) {
        await ctx.open({ ...p.values, season });
        await ctx.view(cam.position, cam.target);
        const file = `season-${p.name}-${id}.png`;
        await ctx.shoot(file);
        shots.push({ file, caption: `${p.label}: ${label} (Season ${season})` });
      }
    }
    return shots;
  },
};

/**
 * Close-ups: preset, Season, the set to frame, camera distance (m), where the camera looks from
 * (`below`: hanging parts, seen from under and outside the leaves; `above`: a fir's upright
 * cones; `out`: level, from outside the crown), caption.
 */
const PARTS = [
  ['cherry', 4.2, 'cherry blossom petals', 0.5, 'out', 'Cherry blossom in April'],
  ['apple', 4.9, 'apple blossom petals', 0.5, 'out', 'Apple blossom in May'],
  ['cherry', 6.1, 'cherries', 0.4, 'below', 'Cherries in June'],
  ['apple', 9.2, 'apples', 0.7, 'below', 'Apples in September'],
  ['oak', 9.5, 'acorns', 0.3, 'below', 'Acorns in their cups, mid-September (Oak)'],
  ['umbrella', 10.1, 'samara wings', 0.3, 'below', 'Ripe samaras in early October (maple leaf)'],
  ['fir', 9.0, 'fir cones', 1.0, 'out', 'Fir cones standing on the upper branches in September'],
  ['weeping', 4.0, 'birch catkins', 0.3, 'below', 'Birch catkins shedding pollen in April'],
  [
    'quaking_aspen',
    3.3,
    'aspen catkins',
    0.3,
    'below',
    'Aspen catkins in March, before the leaves',
  ],
  ['oak', 1.5, 'buds', 0.1, 'out', 'Winter buds at the shoot tips in January (Oak)'],
];

/** Where the camera stands to look at `at` from `distance` m (see PARTS). */
export function partCamera(at, distance, from) {
  const out = Math.hypot(at[0], at[2]) || 1;
  const [ox, oz] = [at[0] / out, at[2] / out];
  const [side, up] = { below: [0.6, -0.8], above: [0.6, 0.8], out: [1, 0.25] }[from];
  return [at[0] + ox * side * distance, at[1] + up * distance, at[2] + oz * side * distance];
}

/** Of `origins`, one on the crown's outside at mid height: the farthest from the trunk's axis. */
export function outermost(origins) {
  const top = Math.max(...origins.map((o) => o[1]));
  const mid = origins.filter((o) => o[1] > 0.3 * top && o[1] < 0.75 * top);
  const list = mid.length > 0 ? mid : origins;
  return list.reduce((a, b) => (Math.hypot(b[0], b[2]) > Math.hypot(a[0], a[2]) ? b : a));
}

export const partsSection = {
  id: 'flowers-and-fruit',
  title: 'Flowers and fruit',
  intro:
    'Close-ups of the Season’s parts at arm’s length: blossom (petals from the leaf pipeline), fruit on its stalks, cones, catkins, winter buds, and the fallen leaves under a maple in November. The camera looks in at a part on the outside of the crown.',
  layout: (shots) => imageTable(shots, 2),
  async shots(ctx) {
    const shots = [];
    const preset = (name) => ctx.presets.find((p) => p.name === name);
    for (const [name, season, set, distance, side, caption] of PARTS) {
      const p = preset(name);
      if (!p || (ctx.presetFilter && !ctx.presetFilter.includes(name))) continue;
      const values = { ...p.values, season };
      const organs = ctx.report('foliage', values).foliage.organs;
      const part = organs.find((o) => o.name === set);
      if (!part) throw new Error(`${name} at Season ${season} has no ${set}`);
      const at = outermost(part.origins);
      const from = partCamera(at, distance, side);
      await ctx.open(values);
      await ctx.view(from, at);
      const file = `part-${set.replaceAll(' ', '-')}.png`;
      await ctx.shoot(file);
      shots.push({ file, caption: `${caption} (Season ${season})` });
    }
    // The fallen leaves: a maple's ground in November, from standing height beside the trunk.
    const maple = preset('umbrella');
    if (maple && (!ctx.presetFilter || ctx.presetFilter.includes('umbrella'))) {
      await ctx.open({ ...maple.values, season: 11.2 });
      await ctx.view([4.5, 1.7, 4.5], [0, 0.2, 0]);
      await ctx.shoot('part-fallen-leaves.png');
      shots.push({
        file: 'part-fallen-leaves.png',
        caption: 'Fallen leaves under the maple-leaved Umbrella Tree in November (Season 11.2)',
      });
    }
    return shots;
  },
};
