// Gallery section: close-ups at the distance a user inspects a tree from: the four bark types on
// species trunks, a shifted fork, a branch collar, tree holes (the and the default size),
// a leaf cluster, conifer needles and a cut branch's stump (end grain in its bark rim, and the
// callus closing over it in the years after the cut), opened from a share link's `e=`. Camera
// positions come from the native CLI's reports of the same trees.
import { imageTable } from './context.mjs';

const BARKS = [
  ['oak', 'Furrowed bark (Oak)'],
  ['fir', 'Plated bark (Fir)'],
  ['quaking_aspen', 'Smooth-banded bark (Quaking Aspen)'],
  ['weeping_willow', 'Fibrous bark (Weeping Willow)'],
];

const add = (a, b, s = 1) => a.map((x, i) => x + b[i] * s);

export const closeupsSection = {
  id: 'closeups',
  title: 'Close-ups',
  intro:
    'Bark types on species trunks at about a metre, a fork, a branch collar, tree holes, a leaf cluster, conifer needles and the stump of a cut branch (fresh, then closing over with woundwood in the years after the cut), as a user sees them up close.',
  layout: (shots) => imageTable(shots, 2),
  async shots(ctx) {
    const shots = [];
    const shot = async (file, caption) => {
      await ctx.shoot(file);
      shots.push({ file, caption });
    };
    const preset = (name) => ctx.presets.find((p) => p.name === name).values;
    for (const [name, caption] of BARKS) {
      // A straight trunk (no random bend) so the camera knows where it is.
      const values = { ...preset(name), l0_curve_v: 0 };
      const r = ctx.report('skeleton', values).skeleton[0].radius;
      await ctx.open(values);
      await ctx.view([r * 4.5, 1.7, r * 2.5], [0, 1.4, 0]);
      await shot(`bark-${name}.png`, caption);
    }
    // The shifted fork of the issue (CA Black Oak, trunk only): the trunk splits at its first joint.
    const fork = { ...preset('ca_black_oak'), levels: 1, leaves: 0, l0_curve_v: 0 };
    const split = ctx.report('skeleton', fork).skeleton.find((s) => s.split_clone);
    const h = split ? split.base_height : 1.2;
    await ctx.open(fork);
    await ctx.view([1.6, h + 0.6, 1.9], [0, h + 0.3, 0]);
    await shot('fork.png', 'Fork: CA Black Oak trunk splitting (levels=1, leaves off)');
    // From the other side: the second clone of the three-way base split (issue #17's knee).
    await ctx.view([-2.6, h + 1.4, 3.2], [0, h + 1.0, 0]);
    await shot(
      'fork-side.png',
      'The same three-way split from the other side: the second clone leaves without a knee',
    );
    // A branch collar on the default tree's straight trunk, at its lowest level-1 branch.
    const collar = { l0_curve_v: 0, leaves: 0 };
    const stems = ctx.report('skeleton', collar).skeleton;
    const branch = stems
      .filter((s) => s.level === 1)
      .sort((a, b) => a.base_height - b.base_height)[0];
    const r0 = stems[0].radius;
    const at = branch ? branch.base_height : 5;
    await ctx.open(collar);
    await ctx.view([r0 * 9, at + r0 * 2, r0 * 6], [0, at, 0]);
    await shot('collar.png', 'Branch collars on the default tree (leaves off)');
    // Tree holes: the (hole_count=3, hole_size=0.7, hole_depth=0.8) and the default size.
    for (const [file, values, caption] of [
      [
        'hole.png',
        { hole_count: 3, hole_size: 0.7, hole_depth: 0.8 },
        'Tree hole (hole_count=3, hole_size=0.7, hole_depth=0.8)',
      ],
      [
        'hole-default.png',
        { hole_count: 3 },
        'Tree hole at the default size and depth (hole_count=3)',
      ],
    ]) {
      const holes = ctx.report('mesh', values).hole_list ?? [];
      const hole =
        holes.filter((x) => x.centre[1] > 0.5).sort((a, b) => b.radius - a.radius)[0] ?? holes[0];
      if (!hole) continue;
      await ctx.open(values);
      const away = Math.max(hole.radius * 5, 0.7);
      const eye = add(add(hole.centre, hole.normal, away), [0, 1, 0], away * 0.3);
      await ctx.view(eye, hole.centre);
      await shot(file, caption);
    }
    // A leaf cluster on the oak, from just outside the crown's shell.
    const cam = await ctx.open(preset('oak'));
    const [p, t] = [cam.position, cam.target];
    await ctx.view(
      add(t, add(p, t, -1), 0.42),
      add(add(t, add(p, t, -1), 0.3), [0, 1, 0], 0.1 * t[1]),
    );
    await shot('leaves.png', 'A leaf cluster on the Oak: crown-depth shading, translucency');
    // Conifer shoots on the fir's lower crown, from just outside it: needles in two flat ranks.
    const firCam = await ctx.open(preset('fir'));
    const [fp, ft] = [firCam.position, firCam.target];
    const low = [ft[0], 0.55 * ft[1], ft[2]];
    await ctx.view(add(low, add(fp, ft, -1), 0.16), add(low, add(fp, ft, -1), 0.06));
    await shot('needles.png', 'Fir shoots from just outside the crown: needles in two flat ranks');
    // A main branch of the default tree cut 0.6 m out from the trunk (a share link's `e=`): the
    // stump's end grain inside its bark rim, up close and from a step back. The point lies on a
    // level-1 stem 15 % of its length out; the camera looks down the stem at the face.
    const cut = [-0.19, 5.94, 0.59];
    const along = [-0.328, 0.236, 0.915];
    const edits = `1~c${cut.map((x) => Math.round(x * 100)).join('.')}`;
    await ctx.open({}, edits);
    await ctx.view(add(add(cut, along, 0.2), [0.05, 0.06, 0]), add(cut, along, -0.02));
    await shot('cut-stump.png', 'A cut main branch of the default tree: end grain in a bark rim');
    await ctx.view(add(add(cut, along, 1.2), [0.3, 0.4, 0]), cut);
    await shot('cut-stump-far.png', 'The same cut from a step back');
    // The same cut made in year 40 (the default tree's Age), seen 1, 2 and 5 years later: the
    // callus rolls in over the end grain from the bark rim (about 1 cm a year) and closes.
    for (const years of [1, 2, 5]) {
      // The life over decades off (no shedding, thickening or drooping): only the callus.
      const still = { shed_light: 0, ring_width: 0, droop: 0 };
      await ctx.open({ age: 40 + years, ...still }, `${edits}.40`);
      await ctx.view(add(add(cut, along, 0.2), [0.05, 0.06, 0]), add(cut, along, -0.02));
      const when = years === 1 ? 'a year' : `${years} years`;
      await shot(
        `cut-callus-${years}.png`,
        `The same cut ${when} after it was made: woundwood rolls over the face`,
      );
    }
    return shots;
  },
};
