// Gallery section: every preset at three angles: as framed on opening, from the side (orbited
// 120°), and from under the crown near the trunk looking up (inner shading, translucent leaves).
import { imageTable, orbit } from './context.mjs';

export const presetsSection = {
  id: 'presets',
  title: 'Presets',
  intro:
    'Every preset at three angles: as the viewer frames it, from the side, and from under the crown (bark, inner shade, leaves against the sun).',
  layout: (shots) => imageTable(shots, 3),
  async shots(ctx) {
    const shots = [];
    for (const p of ctx.presets) {
      if (ctx.presetFilter && !ctx.presetFilter.includes(p.name)) continue;
      const cam = await ctx.open(p.values);
      const [pos, target] = [cam.position, cam.target];
      await ctx.shoot(`${p.name}-front.png`);
      shots.push({ file: `${p.name}-front.png`, caption: `${p.label}: front` });
      await ctx.view(orbit(pos, target, 120), target);
      await ctx.shoot(`${p.name}-side.png`);
      shots.push({ file: `${p.name}-side.png`, caption: `${p.label}: side` });
      // Under the crown: beside the trunk at eye height, looking up into the crown.
      const dir = [pos[0] - target[0], pos[2] - target[2]];
      const len = Math.hypot(dir[0], dir[1]) || 1;
      const out = 0.22 * target[1];
      const under = [target[0] + (dir[0] / len) * out, 1.6, target[2] + (dir[1] / len) * out];
      await ctx.view(orbit(under, target, -60), [target[0], target[1] * 1.3, target[2]]);
      await ctx.shoot(`${p.name}-under.png`);
      shots.push({ file: `${p.name}-under.png`, caption: `${p.label}: under the crown` });
    }
    return shots;
  },
};
