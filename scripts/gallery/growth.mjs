// Gallery section: trees through their years (Age): Weber & Penn trees at 2, 5, 10 and 20 years,
// the Mature Age, and 20 and 60 years past it (the life over decades: thickening, shedding,
// drooping), every grown preset at 2, 5, 10, 20, 40 and 60 years (annual flushes, then the life
// over decades), one row per preset, seen from the mature tree's camera; then the knot a shed
// branch leaves on an old trunk, up close.
import { imageTable } from './context.mjs';

/** The presets shown growing. */
const TREES = [
  'default',
  'oak',
  'fir',
  'grown_broadleaf',
  'grown_shrub',
  'grown_hedgerow',
  'grown_beside_wall',
  'grown_bushy',
];

/**
 * The ages a row shows (seven): a Weber & Penn tree at 2, 5, 10, 20 years, mature, and 20 and 60
 * years past it; a grown tree at 2, 5, 10, 20, 40 and 60 years with its Mature Age among them
 * (and 80 when it is one of them).
 */
export function rowAges(name, mature) {
  if (!name.startsWith('grown_')) {
    return [2, 5, 10, 20, mature]
      .filter((a, i, all) => a <= mature && all.indexOf(a) === i)
      .concat([mature + 20, mature + 60]);
  }
  const ages = [...new Set([2, 5, 10, 20, 40, 60, mature])].sort((a, b) => a - b);
  return ages.length < 7 ? ages.concat([80]) : ages;
}

export const growthSection = {
  id: 'growth',
  title: 'Growth over years',
  intro:
    "The Age slider below the Mature Age replays the growth that led to the mature tree: each stem is born the year after its parent reached it and grows along a Chapman-Richards curve, its radius by a ring a year. Past the Mature Age the tree lives on: the pipe model thickens it, shaded branches die and leave stubs that close into knots, main branches sink under their load with their tips turned up. Each row keeps the mature tree's camera; a grown tree's years are its annual flushes (its growth iterations spread over its years). Last, up close: a knot where a shaded main branch dropped.",
  layout: (shots) => imageTable(shots, 7),
  async shots(ctx) {
    const shots = [];
    for (const name of TREES) {
      const p = ctx.presets.find((q) => q.name === name);
      if (!p || (ctx.presetFilter && !ctx.presetFilter.includes(p.name))) continue;
      const mature = p.values.maturity ?? 40;
      const cam = await ctx.open(p.values);
      for (const age of rowAges(p.name, mature)) {
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
    // A knot: the default tree at 100 years with more shedding (Shedding Light 0.45), where a
    // shaded main branch dropped decades ago; the stub's end (from the native CLI's skeleton of
    // the same tree) seen from beside the trunk.
    if (!ctx.presetFilter) {
      const stub = [0.1085, 7.35, -0.1573];
      const out = [0.3488, 0, -0.9372];
      await ctx.open({ age: 100, shed_light: 0.45 });
      const eye = [stub[0] + out[0] * 0.9, stub[1] + 0.25, stub[2] + out[2] * 0.9];
      await ctx.view(eye, stub);
      await ctx.shoot('knot.png');
      shots.push({
        file: 'knot.png',
        caption: 'The default tree at 100 years: a knot where a shaded main branch dropped',
      });
    }
    return shots;
  },
};
