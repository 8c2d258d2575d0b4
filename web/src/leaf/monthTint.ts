/**
 * The leaf inspector's Season colour: the mean tint of the leaves on the tree shown (the core's
 * seasonal colours, averaged in the generator worker: `TreeUpdate.leafTint`), kept in a tiny
 * external store the viewer writes and the inspector reads, and laid over the leaf drawing as
 * an SVG colour-matrix filter in linear light (what the tint multiplies in the viewer and the
 * exports) at the drawing's lightness ([`drawingTint`]). July's tint is about 1 (the drawing as
 * drawn), October's aspen golden, a maple's red, and a bare tree's none (the drawing untinted,
 * marked `data-month-tint="none"`).
 */

/** A linear-light RGB multiplier, or null when no leaf is on the tree. */
export type MonthTint = [number, number, number] | null;

/** Id of the filter element inside the inspector's SVG. */
export const MONTH_TINT_FILTER_ID = 'sylva-month-tint';

const SVG_NS = 'http://www.w3.org/2000/svg';

/** Top-level elements of the leaf drawing left untinted: the paper and the caption. */
const UNTINTED = new Set(['rect', 'text']);

/**
 * The blade's green the leaf tints multiply, in linear light: the core's `BLADE`
 * (core-rs/sylva-core/src/leaf/texture.rs, sRGB 0.30, 0.52, 0.18) decoded.
 */
const BLADE_LINEAR: [number, number, number] = [0.0732, 0.233, 0.0272];

/** Relative luminance weights of linear sRGB (ITU-R BT.709). */
const LUMA = [0.2126, 0.7152, 0.0722] as const;

/**
 * `tint` for the drawing: divided by how much it brightens or darkens the blade (the
 * luminance of tint × blade over the blade's), so the drawing keeps its lightness and takes the
 * Season's hue. The crown's shade darkens every leaf alike (the mean July tint is about 0.44
 * grey) while the drawing shows one leaf; autumn's golds and reds are many times the blade's
 * red.
 */
export function drawingTint(tint: [number, number, number]): [number, number, number] {
  const luma = (c: readonly number[]) => c.reduce((s, v, i) => s + v * LUMA[i]!, 0);
  const shown = luma(tint.map((t, i) => Math.max(0, t) * BLADE_LINEAR[i]!));
  const scale = shown > 1e-6 ? luma(BLADE_LINEAR) / shown : 1;
  return tint.map((t) => Math.max(0, t) * scale) as [number, number, number];
}

/** The tint of the tree on screen; subscribers are told when it changes. */
export class MonthTintStore {
  private tint: MonthTint = null;
  private readonly listeners = new Set<() => void>();

  /** The current tint. */
  readonly get = (): MonthTint => this.tint;

  /** Subscribes to changes; returns the unsubscribe function. */
  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  /** Sets the tint (nothing happens when it is the same). */
  set(tint: MonthTint): void {
    const old = this.tint;
    if (old === tint || (old && tint && old.every((c, i) => c === tint[i]))) return;
    this.tint = tint;
    for (const listener of this.listeners) listener();
  }
}

/** The app's store: the viewer writes it with every tree, the leaf inspector reads it. */
export const monthTint = new MonthTintStore();

/**
 * Tints `svg` by `tint`: its children move into a group drawn through a `feColorMatrix`
 * multiplying R, G and B in linear light (`color-interpolation-filters="linearRGB"`). An earlier
 * tint is replaced; null removes it.
 */
export function applyMonthTint(svg: SVGSVGElement, tint: MonthTint): void {
  const doc = svg.ownerDocument;
  svg.querySelector(`#${MONTH_TINT_FILTER_ID}`)?.remove();
  let group = svg.querySelector<SVGGElement>(':scope > g[data-month-tint-group]');
  if (!group) {
    // The leaf goes through the filter; the paper behind it and the caption stay as they are.
    group = doc.createElementNS(SVG_NS, 'g');
    group.setAttribute('data-month-tint-group', '');
    const leaf = Array.from(svg.childNodes).filter((n) => !UNTINTED.has(n.nodeName));
    // In the place of the first leaf element: after the paper, so the paper stays behind.
    svg.insertBefore(group, leaf.find((n) => n.nodeType === 1) ?? null);
    group.append(...leaf);
  }
  if (!tint) {
    group.removeAttribute('filter');
    svg.setAttribute('data-month-tint', 'none');
    return;
  }
  const [r, g, b] = drawingTint(tint).map((c) => c.toFixed(4));
  const filter = doc.createElementNS(SVG_NS, 'filter');
  filter.setAttribute('id', MONTH_TINT_FILTER_ID);
  filter.setAttribute('color-interpolation-filters', 'linearRGB');
  const matrix = doc.createElementNS(SVG_NS, 'feColorMatrix');
  matrix.setAttribute('type', 'matrix');
  matrix.setAttribute('values', `${r} 0 0 0 0  0 ${g} 0 0 0  0 0 ${b} 0 0  0 0 0 1 0`);
  filter.append(matrix);
  svg.prepend(filter);
  group.setAttribute('filter', `url(#${MONTH_TINT_FILTER_ID})`);
  svg.setAttribute('data-month-tint', `${r} ${g} ${b}`);
}
