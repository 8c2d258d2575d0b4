// Gallery section: three broadleaf presets through the year (Season: April's flush, July, their
// species' autumn peak, bare January), one row each, seen from the same camera as July.
import { imageTable } from './context.mjs';

/** The presets and the Season of their autumn picture (each species' own peak). */
const TREES = [
  { name: 'umbrella', leaf: 'maple', autumn: 10.5 },
  { name: 'oak', leaf: 'oak', autumn: 11 },
  { name: 'quaking_aspen', leaf: 'aspen', autumn: 10.3 },
];

export const seasonsSection = {
  id: 'seasons',
  title: 'Seasons',
  intro:
    "The Season slider on three broadleaf presets (maple, oak and aspen leaves): the spring flush in late April, July, autumn at the species' peak, mid-October to 1 November (sun leaves outside the crown first), and bare January. Each row keeps July's camera.",
  layout: (shots) => imageTable(shots, 4),
  async shots(ctx) {
    const shots = [];
    for (const tree of TREES) {
      const p = ctx.presets.find((q) => q.name === tree.name);
      if (!p || (ctx.presetFilter && !ctx.presetFilter.includes(p.name))) continue;
      const months = [
        ['april', 'late April', 4.8],
        ['july', 'July', 7],
        ['autumn', 'autumn', tree.autumn],
        ['january', 'January', 1.5],
      ];
      const cam = await ctx.open(p.values);
      for (const [id, label, season] of months) {
        await ctx.open({ ...p.values, season });
        await ctx.view(cam.position, cam.target);
        const file = `season-${p.name}-${id}.png`;
        await ctx.shoot(file);
        shots.push({ file, caption: `${p.label} (${tree.leaf}): ${label} (Season ${season})` });
      }
    }
    return shots;
  },
};
