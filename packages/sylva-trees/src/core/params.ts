/** Pure helpers over the parameter registry: defaults, step snapping, presets, grouping. */
import type { ParamSpec, Params, Preset, Stage } from './types';

/** Number of decimals in a number's plain or exponent notation (0.05 → 2, 1e-7 → 7). */
export function decimalsOf(x: number): number {
  if (!Number.isFinite(x) || Number.isInteger(x)) return 0;
  const [mantissa = '', exp = '0'] = String(x).toLowerCase().split('e');
  const frac = mantissa.split('.')[1] ?? '';
  return Math.max(0, frac.length - Number(exp));
}

function clamp(x: number, lo: number, hi: number): number {
  return Math.min(hi, Math.max(lo, x));
}

/** Largest difference from `reference` still treated as float noise (incl. f32 rounding). */
function noiseTolerance(spec: ParamSpec, reference: number): number {
  return Math.max(Math.max(spec.step, Number.EPSILON) * 1e-6, Math.abs(reference) * 1.2e-7);
}

/** Whether `value` is the default up to float noise (e.g. an f32 default 0.30000001192092896 vs 0.3). */
function nearDefault(spec: ParamSpec, value: number): boolean {
  return Math.abs(value - spec.default) <= noiseTolerance(spec, spec.default);
}

/**
 * Snaps a value onto the param's slider grid (min + k·step), clamped, without float noise;
 * a value that lands on the default (up to float noise) becomes exactly the default.
 */
export function snapToStep(spec: ParamSpec, value: number): number {
  const v = clamp(value, spec.min, spec.max);
  let snapped = v;
  if (spec.step > 0) {
    const k = Math.round((v - spec.min) / spec.step);
    const decimals = Math.min(15, Math.max(decimalsOf(spec.min), decimalsOf(spec.step)));
    snapped = clamp(Number((spec.min + k * spec.step).toFixed(decimals)), spec.min, spec.max);
  }
  if (spec.kind !== 'float') snapped = Math.round(snapped);
  if (nearDefault(spec, snapped)) return spec.default;
  return Object.is(snapped, -0) ? 0 : snapped;
}

/**
 * Canonical form of a value: clamped, integral for int/bool/enum, float noise removed (a float
 * within 1e-6 steps of the grid goes exactly onto it, or onto the default), other values kept.
 * Idempotent, so `normalizeValue(Number(formatNumber(v))) === v` for any normalised v.
 */
export function normalizeValue(spec: ParamSpec, value: number): number {
  if (!Number.isFinite(value)) return spec.default;
  // Returns the default itself: -0 equals a default of 0 under ===, but must not leak out.
  if (value === spec.default) return spec.default;
  const v = clamp(value, spec.min, spec.max);
  if (spec.kind !== 'float') return Math.round(v);
  if (nearDefault(spec, v)) return spec.default;
  if (!(spec.step > 0)) return v;
  const k = (v - spec.min) / spec.step;
  if (Math.abs(k - Math.round(k)) * spec.step > noiseTolerance(spec, v)) {
    return Object.is(v, -0) ? 0 : v;
  }
  return snapToStep(spec, v);
}

/** Short display text for a value: float noise hidden at the step's precision. */
export function displayValue(spec: ParamSpec, value: number): string {
  if (spec.kind !== 'float') return String(value);
  const decimals = Math.min(15, Math.max(decimalsOf(spec.min), decimalsOf(spec.step)));
  const short = Number(value.toFixed(decimals));
  if (Math.abs(short - value) <= noiseTolerance(spec, value)) return String(short);
  return String(Number(value.toPrecision(8)));
}

/** The default value of every parameter. */
export function defaultParams(registry: readonly ParamSpec[]): Params {
  const out: Params = {};
  for (const spec of registry) out[spec.id] = spec.default;
  return out;
}

/** Defaults overlaid with a preset's values (unknown ids in the preset are dropped). */
export function applyPreset(registry: readonly ParamSpec[], preset: Preset): Params {
  const out = defaultParams(registry);
  for (const spec of registry) {
    const v = preset.values[spec.id];
    if (v !== undefined) out[spec.id] = normalizeValue(spec, v);
  }
  return out;
}

/** Every preset applied to the defaults, per preset list (and the registry it was applied with). */
const appliedPresets = new WeakMap<
  readonly Preset[],
  { registry: readonly ParamSpec[]; applied: Params[] }
>();

/**
 * The preset whose values exactly reproduce `params`, if any. The app asks on every slider step:
 * the presets are applied once per list, and each comparison stops at the first difference.
 */
export function matchingPreset(
  registry: readonly ParamSpec[],
  presets: readonly Preset[],
  params: Params,
): Preset | undefined {
  let cached = appliedPresets.get(presets);
  if (cached?.registry !== registry) {
    cached = { registry, applied: presets.map((p) => applyPreset(registry, p)) };
    appliedPresets.set(presets, cached);
  }
  const { applied } = cached;
  const i = applied.findIndex((expected) => registry.every((s) => expected[s.id] === params[s.id]));
  return i < 0 ? undefined : presets[i];
}

/** Parameters grouped by `group`, in registry (display) order. */
export function groupParams(registry: readonly ParamSpec[]): [string, ParamSpec[]][] {
  const groups = new Map<string, ParamSpec[]>();
  for (const spec of registry) {
    const list = groups.get(spec.group);
    if (list) list.push(spec);
    else groups.set(spec.group, [spec]);
  }
  return [...groups.entries()];
}

/** A uniformly random integer seed within the seed param's range. */
export function randomSeed(spec: ParamSpec, random: () => number = Math.random): number {
  const lo = Math.ceil(spec.min);
  const hi = Math.floor(spec.max);
  return lo + Math.floor(random() * (hi - lo + 1));
}

const STAGE_ORDER: readonly Stage[] = ['skeleton', 'mesh', 'foliage', 'leaf', 'viewer'];

/**
 * The first pipeline stage whose parameters differ between `a` and `b` (the registry's
 * `stage`; a spec without one counts as `skeleton`), or null when none differs. `viewer`
 * means nothing needs regenerating.
 */
export function firstStage(registry: readonly ParamSpec[], a: Params, b: Params): Stage | null {
  let first: number | null = null;
  for (const spec of registry) {
    const x = a[spec.id] ?? spec.default;
    const y = b[spec.id] ?? spec.default;
    if (Object.is(x, y)) continue;
    const rank = STAGE_ORDER.indexOf(spec.stage ?? 'skeleton');
    if (first === null || rank < first) first = rank;
  }
  return first === null ? null : (STAGE_ORDER[first] ?? null);
}
