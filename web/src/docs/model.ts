/**
 * The docs page's parameter reference, built from the registry at run time (the same source as
 * the panel): groups in panel order, and per parameter its label, id, kind, unit, description,
 * default and range as display text.
 */
import { displayValue, groupParams, type ParamSpec, type Preset } from 'sylva-trees/core';
import { formatNumber } from 'sylva-trees/url';

/** One parameter row of the reference. */
export interface DocsParam {
  id: string;
  label: string;
  kind: ParamSpec['kind'];
  unit: string;
  description: string;
  /** The default as shown in the panel (an enum shows its option name). */
  defaultText: string;
  /** The valid values: `min – max` (with step), `0 or 1`, or the enum options. */
  rangeText: string;
}

/** One group (panel section) of the reference. */
export interface DocsGroup {
  name: string;
  /** Anchor id of the section. */
  anchor: string;
  params: DocsParam[];
}

/** One preset of the reference. */
export interface DocsPreset {
  name: string;
  label: string;
  description: string;
}

/** Everything the reference shows. */
export interface DocsModel {
  groups: DocsGroup[];
  presets: DocsPreset[];
  count: number;
}

/** `Crown Shape` → `crown-shape`. */
export function anchorOf(name: string): string {
  return `group-${name
    .toLowerCase()
    .replace(/[^a-z0-9]+/g, '-')
    .replace(/^-|-$/g, '')}`;
}

/** The default as display text: the option name of an enum, yes/no for a bool. */
export function defaultText(spec: ParamSpec): string {
  if (spec.kind === 'enum' && spec.options) {
    const name = spec.options[spec.default];
    return name === undefined ? String(spec.default) : `${spec.default} (${name})`;
  }
  if (spec.kind === 'bool') return spec.default === 1 ? '1 (on)' : '0 (off)';
  return displayValue(spec, spec.default);
}

/** The valid values as display text. */
export function rangeText(spec: ParamSpec): string {
  if (spec.kind === 'bool') return '0 or 1';
  if (spec.kind === 'enum' && spec.options) {
    return spec.options.map((option, i) => `${i} ${option}`).join(', ');
  }
  const range = `${formatNumber(spec.min)} – ${formatNumber(spec.max)}`;
  if (spec.kind === 'int') return spec.step > 1 ? `${range}, step ${spec.step}` : range;
  return spec.step > 0 ? `${range}, step ${formatNumber(spec.step)}` : range;
}

/** Builds the reference from the registry and presets (both from the wasm core). */
export function buildDocsModel(
  registry: readonly ParamSpec[],
  presets: readonly Preset[],
): DocsModel {
  // The panel shows the seed on its own above the groups; the reference keeps it in its group.
  const groups = groupParams(registry).map(([name, specs]) => ({
    name,
    anchor: anchorOf(name),
    params: specs.map((spec) => ({
      id: spec.id,
      label: spec.label,
      kind: spec.kind,
      unit: spec.unit,
      description: spec.description,
      defaultText: defaultText(spec),
      rangeText: rangeText(spec),
    })),
  }));
  return {
    groups,
    presets: presets.map(({ name, label, description }) => ({ name, label, description })),
    count: registry.length,
  };
}
