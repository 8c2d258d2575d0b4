// Gallery section: trees through their years (Age): the growth replay at 2, 5, 10 and 20 years
// and at the Mature Age, one row per preset, seen from the mature tree's camera.
import { imageTable } from './context.mjs';

/** The presets shown growing. */
const TREES = ['default', 'oak', 'fir', 'grown_broadleaf'];

export const growthSection = {
  id: 'growth',
  title: 'Growth over years',
  intro:
    "The Age slider below the Mature Age replays the growth that led to the mature tree: each stem is born the year after its parent reached it and grows along a Chapman-Richards curve, its radius by a ring a year. Each row keeps the mature tree's camera. (A grown tree's years are its stems' replay too, until its growth is grouped into annual flushes.)",
  layout: (shots) => imageTable(shots, 5),
  async shots(ctx) {
    const shots = [];
    for (const name of TREES) {
      const p = ctx.presets.find((q) => q.name === name);
      if (!p || (ctx.presetFilter && !ctx.presetFilter.includes(p.name))) continue;
      const mature = p.values.maturity ?? 40;
      const cam = await ctx.open(p.values);
      for (const age of [2, 5, 10, 20, mature].filter(
        (a, i, all) => a <= mature && all.indexOf(a) === i,
      )) {
        await ctx.open({ ...p.values, age });
        await ctx.view(cam.position, cam.target);
        const file = `growth-${p.name}-${age}.png`;
        await ctx.shoot(file);
        shots.push({
          file,
          caption: `${p.label}: ${age} years${age === mature ? ' (mature)' : ''}`,
        });
      }
    }
    return shots;
  },
};
