/**
 * The parts the parameter panel and the leaf inspector share: one collapsible section per
 * registry group, and the options of a preset picker.
 */
import type { ReactNode } from 'react';
import type { Params, ParamSpec, Preset } from 'sylva-trees/core';
import { ParamControl } from './ParamControl';

interface Props {
  /** The groups in order, each with its parameters (`groupParams`). */
  groups: [string, ParamSpec[]][];
  params: Params;
  onChange: (id: ParamSpec['id'], value: number, interactive?: boolean) => void;
  /** Whether the section of `group` (at `index`) starts open. */
  open: (group: string, index: number) => boolean;
  /** Extra controls shown at the top of a group's section (e.g. the growth editor's tools). */
  extras?: Partial<Record<string, ReactNode>>;
}

/** See the module comment. */
export function ParamGroups({ groups, params, onChange, open, extras }: Props) {
  return groups.map(([group, specs], index) => (
    <details key={group} className="group" open={open(group, index)} data-group={group}>
      <summary>{group}</summary>
      {extras?.[group] ?? null}
      {specs.map((spec) => (
        <ParamControl
          key={spec.id}
          spec={spec}
          value={params[spec.id] ?? spec.default}
          onChange={onChange}
        />
      ))}
    </details>
  ));
}

/** One `<option>` per preset (its name as the value, the description as a tooltip). */
export function PresetOptions({ presets }: { presets: readonly Preset<string>[] }) {
  return presets.map((p) => (
    <option key={p.name} value={p.name} title={p.description}>
      {p.label}
    </option>
  ));
}
