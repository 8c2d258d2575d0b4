/**
 * The leaf inspector's Season colour: the mean tint of the leaves on the tree shown (the core's
 * seasonal colours, averaged in the generator worker: `TreeUpdate.leafTint`), kept in a tiny
 * external store the viewer writes and the inspector reads, and laid over the leaf drawing as
 * an SVG colour-matrix filter in linear light (what the tint multiplies in the viewer and the
 * exports), divided by its largest channel. July's tint is about 1 (the drawing as drawn),
 * October's aspen golden, a maple's red, and a bare tree's none (the drawing untinted, marked
 * `data-month-tint="none"`).
 */

/** A linear-light RGB multiplier, or null when no leaf is on the tree. */
export type MonthTint = [number, number, number] | null;

/** Id of the filter element inside the inspector's SVG. */
export const MONTH_TINT_FILTER_ID = 'sylva-month-tint';

const SVG_NS = 'http://www.w3.org/2000/svg';

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
    group = doc.createElementNS(SVG_NS, 'g');
    group.setAttribute('data-month-tint-group', '');
    group.append(...Array.from(svg.childNodes));
    svg.append(group);
  }
  if (!tint) {
    group.removeAttribute('filter');
    svg.setAttribute('data-month-tint', 'none');
    return;
  }
  // At the drawing's brightness: the crown's shade darkens every leaf alike (the mean July
  // tint is about 0.45 grey), the drawing shows one leaf in the open.
  const top = Math.max(...tint, 1e-6);
  const [r, g, b] = tint.map((c) => Math.max(0, c / top).toFixed(4));
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
