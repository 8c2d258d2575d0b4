// Gallery section: the Shape by hand tools (docs/user-guide.md "Shape by hand"), each as a before
// and after from the same camera: a paint stroke on the default tree and on Grown: Broadleaf, a
// drawn crown outline, two main branches cut, a main branch bent down, and the bent branch up
// close (leaves off). The edits are written in the JSON form of docs/formats.md "Hand edits" and
// opened as a share link's `e=`; every edit must resolve natively and the page must show the
// native tree's hash, else the section fails.
//
// The branch points were found on the native default tree (seed 1): its bark (`sylva generate
// --leaves none --out bark.obj`) gave candidate points 0.45 to 0.6 m from the trunk's axis, a cut
// at each told by the stems it removed (26 to 28) that it lies on a main branch, and the rings
// of that branch's own bark (the same tree with levels=2, whose main branches are the same)
// gave points on its axis.

/** The brush the studio's Paint tool starts with (docs/user-guide.md "Shape by hand"). */
const BRUSH = { radius: 0.6, density: 400, segment: 0.25, kill: 0.4 };
/** Brush points lie this far apart along a stroke, as the studio lays them while dragging (m). */
const BRUSH_STEP = 0.2;

/** Brush points `BRUSH_STEP` apart along the polyline `corners` (tree space, m). */
export function strokePoints(corners) {
  const out = [corners[0]];
  for (let i = 1; i < corners.length; i++) {
    const [a, b] = [corners[i - 1], corners[i]];
    const n = Math.max(1, Math.round(Math.hypot(...b.map((x, j) => x - a[j])) / BRUSH_STEP));
    for (let k = 1; k <= n; k++) out.push(a.map((x, j) => x + ((b[j] - x) * k) / n));
  }
  return out;
}

const cm = (x) => Math.round(x * 100);
/** The first point in centimetres, then every next one's difference to the one before. */
const deltas = (points) =>
  points.flatMap((p, i) => (i === 0 ? p.map(cm) : p.map((x, j) => cm(x) - cm(points[i - 1][j]))));

/**
 * A share link's `e=` value of an edit list in the JSON form (docs/formats.md "Hand edits"; the
 * app's encoder is encodeEdits in packages/sylva-trees/src/url/editsCodec.ts).
 */
export function editsLink(edits) {
  const item = (e) => {
    switch (e.op) {
      case 'paint':
        return `p${[cm(e.radius), e.density, cm(e.segment), cm(e.kill), ...deltas(e.points)].join('.')}`;
      case 'crown':
        return `o${deltas(e.outline).join('.')}`;
      case 'cut':
        return `c${e.at.map(cm).join('.')}`;
      case 'bend':
        return `b${[...e.at, ...e.to].map(cm).join('.')}`;
      default:
        throw new Error(`unknown edit op ${e.op}`);
    }
  };
  return ['1', ...edits.map(item)].join('~');
}

/** The edits on the link's centimetre grid, as the studio keeps them. */
const onGrid = (edits) =>
  JSON.parse(
    JSON.stringify(edits, (k, v) => (typeof v === 'number' && k !== 'density' ? cm(v) / 100 : v)),
  );

/** The default tree's whole-tree camera: from the front (+z), the crown's sides in silhouette. */
const WHOLE = [
  [0, 7.5, 28],
  [0, 7.5, 0],
];

/**
 * Before/after pairs: `values` (parameters over `preset`'s), `edits` (JSON form), the camera
 * (`view`, else WHOLE), the after's caption and file (`shape-ID.png` unless given) and the
 * before's (the default tree's whole view, `shape-tree.png`, unless given).
 */
const PAIRS = [
  {
    id: 'paint',
    edits: [
      // One stroke sweeping out of the crown's right side at mid-height, on the trunk's plane.
      {
        op: 'paint',
        points: strokePoints([
          [3, 8, 0.3],
          [5, 8.2, 0.3],
          [7, 8.8, 0.3],
        ]),
        ...BRUSH,
      },
    ],
    after: 'Paint: one stroke out of the right side at 8 m; a new limb grows along it',
  },
  {
    id: 'grown-paint',
    preset: 'grown_broadleaf',
    // The preset's own camera (the embed's framing), the stroke on the upright plane through the
    // trunk facing it, sweeping out of the crown's right side and up.
    view: [
      [10.97, 8.82, 14.72],
      [-0.04, 4.12, 0.04],
    ],
    edits: [
      {
        op: 'paint',
        points: strokePoints(
          [
            [3, 4.5],
            [4.5, 5],
            [6, 6.2],
            [6.8, 7.8],
          ].map(([s, y]) => [0.8 * s, y, -0.6 * s]),
        ),
        ...BRUSH,
      },
    ],
    before: { file: 'shape-grown-paint-before.png', caption: 'Grown: Broadleaf' },
    after: 'Paint on Grown: Broadleaf: a stroke out and up from the crown; it grows into it',
  },
  {
    id: 'crown',
    values: { shape: 8 },
    // A lollipop: a ball from 8 to 13.5 m, 3.5 m wide at 10 m; the branches below get none.
    edits: [
      {
        op: 'crown',
        outline: [
          [0, 8],
          [2.5, 8.5],
          [3.5, 10],
          [3, 12],
          [1.5, 13.2],
          [0, 13.5],
        ],
      },
    ],
    after:
      'Crown: a drawn lollipop outline, a ball 8 to 13.5 m up (Crown Shape Drawn); the branches follow it',
  },
  {
    id: 'cut',
    // The two lowest main branches on the left (they leave the trunk at 5.4 and 6.2 m, toward -x),
    // each cut about half a metre out.
    edits: [
      { op: 'cut', at: [-0.52, 5.51, 0.12] },
      { op: 'cut', at: [-0.52, 6.28, 0.03] },
    ],
    after: 'Cut: the two lowest main branches on the left cut; the crown starts higher there',
  },
  {
    id: 'bend',
    // The lowest main branch on the left (base 5.4 m on the trunk, 3.85 m long): its axis point
    // 2.6 m from the base, 20° above level, goes to 35° below level at the same distance.
    edits: [{ op: 'bend', at: [-2.43, 6.32, 0.51], to: [-2.11, 3.92, 0.45] }],
    after: 'Bend: the lowest main branch on the left bent down; its twigs and leaves ride along',
  },
  {
    id: 'bend-closeup',
    values: { leaves: 0 },
    // Beside the same branch, below the crown, looking at its junction with the trunk.
    view: [
      [-1.5, 5.0, 2.6],
      [-0.7, 4.9, 0.15],
    ],
    edits: [{ op: 'bend', at: [-2.43, 6.32, 0.51], to: [-2.11, 3.92, 0.45] }],
    before: {
      file: 'bend-closeup-before.png',
      caption: 'The same branch up close before the bend (leaves off)',
    },
    file: 'bend-closeup.png',
    after: 'Bent up close: a smooth curve from the welded junction with the trunk',
  },
];

export const handEditsSection = {
  id: 'shape',
  title: 'Shape by hand',
  intro:
    "The Shape by hand tools ([user guide](user-guide.md#shape-by-hand)), each before and after from the same camera, opened from a share link's `e=`: a paint stroke with the studio's default brush (points 0.2 m apart, radius 0.6 m, density 400, segment 0.25 m, kill distance 0.4 m) on the default tree and on Grown: Broadleaf, a drawn crown outline, two main branches cut, a main branch bent down and, up close with leaves off, the bend's curve and its junction with the trunk. A cut branch's stump up close is under Close-ups (`cut-stump.png`, `cut-stump-far.png`).",
  layout: (shots) => {
    const cell = (s) => `![${s.caption}](gallery/${s.file})<br>${s.caption}`;
    const rows = ['| Before | After |', '|---|---|'];
    for (let i = 0; i + 1 < shots.length; i += 2)
      rows.push(`| ${cell(shots[i])} | ${cell(shots[i + 1])} |`);
    return rows;
  },
  async shots(ctx) {
    const shots = [];
    const taken = new Set();
    for (const pair of PAIRS) {
      if (ctx.presetFilter && !ctx.presetFilter.includes(pair.preset ?? 'default')) continue;
      const preset = pair.preset ? ctx.presets.find((p) => p.name === pair.preset) : null;
      const values = { ...(preset?.values ?? {}), ...(pair.values ?? {}) };
      const view = pair.view ?? WHOLE;
      const edits = onGrid(pair.edits);
      const native = ctx.edited(values, edits);
      const unresolved = native.edits.filter((e) => !e.resolved);
      if (unresolved.length) {
        throw new Error(`shape/${pair.id}: unresolved edits ${JSON.stringify(unresolved)}`);
      }
      // Before: the tree without the edits (the default tree's whole view is shot once; a drawn
      // crown without its outline is the default tree's Cylindrical crown).
      const before = pair.before ?? { file: 'shape-tree.png', caption: 'The default tree' };
      if (!taken.has(before.file)) {
        await ctx.open(pair.before ? values : {});
        await ctx.view(...view);
        await ctx.shoot(before.file);
        taken.add(before.file);
      }
      shots.push(before);
      await ctx.open(values, editsLink(edits));
      const shown = await ctx.shownHash();
      if (shown !== native.hash) {
        throw new Error(
          `shape/${pair.id}: the page shows ${shown}, the native tree ${native.hash}`,
        );
      }
      await ctx.view(...view);
      const after = pair.file ?? `shape-${pair.id}.png`;
      await ctx.shoot(after);
      shots.push({ file: after, caption: pair.after });
    }
    return shots;
  },
};
