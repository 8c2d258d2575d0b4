/** Side panel generated from the registry: presets, seed, Reset, and one section per group. */
import { groupParams, type Params, type ParamSpec, type Preset } from 'sylva-trees/core';
import type { ReactNode } from 'react';
import { NumberField } from './NumberField';
import { ParamGroups, PresetOptions } from './ParamGroups';

interface Props {
  registry: readonly ParamSpec[];
  presets: readonly Preset[];
  params: Params;
  activePreset: Preset['name'] | null;
  version: string;
  /** Threads a generation uses (2: the threaded core in a cross-origin isolated page). */
  threads: number;
  onChange: (id: ParamSpec['id'], value: number, interactive?: boolean) => void;
  onPreset: (name: string) => void;
  onRandomize: () => void;
  onReset: () => void;
  canUndo: boolean;
  canRedo: boolean;
  onUndo: () => void;
  onRedo: () => void;
  /** Extra controls shown at the top of a group's section (e.g. the growth editor's tools). */
  extras?: Partial<Record<string, ReactNode>>;
}

/** The Undo and Redo buttons. */
const HISTORY_BUTTONS = [
  {
    id: 'undo',
    label: 'Undo',
    title: 'Undo the last parameter change (Ctrl+Z)',
    keys: 'Control+Z Meta+Z',
  },
  {
    id: 'redo',
    label: 'Redo',
    title: 'Redo (Ctrl+Shift+Z or Ctrl+Y)',
    keys: 'Control+Shift+Z Control+Y Meta+Shift+Z',
  },
] as const;

/** The parameter editor; seed gets its own field with a Randomize button. */
export function ParamPanel(props: Props) {
  const { registry, presets, params, activePreset, onChange } = props;
  const seedSpec = registry.find((s) => s.id === 'seed');
  const groups = groupParams(registry.filter((s) => s !== seedSpec));
  const activeDescription = presets.find((p) => p.name === activePreset)?.description ?? '';
  return (
    <aside className="panel" aria-label="Tree parameters">
      <header className="panel-header">
        <h1>Sylva</h1>
        <span
          className="version"
          title={
            props.threads > 1
              ? `Core version; generating on ${props.threads} threads (the page is cross-origin isolated)`
              : 'Core version; generating on one thread'
          }
        >
          core {props.version}
          {props.threads > 1 ? ` · ${props.threads} threads` : ''}
        </span>
      </header>

      <div className="panel-block">
        <label htmlFor="preset-picker" className="param-label">
          Preset
        </label>
        <select
          id="preset-picker"
          data-testid="preset-picker"
          value={activePreset ?? ''}
          title={activeDescription}
          onChange={(e) => props.onPreset(e.currentTarget.value)}
        >
          {activePreset === null ? (
            <option value="" disabled>
              Custom
            </option>
          ) : null}
          <PresetOptions presets={presets} />
        </select>
      </div>

      {seedSpec ? (
        <div className="panel-block" title={seedSpec.description}>
          <label htmlFor="seed-field" className="param-label">
            {seedSpec.label}
          </label>
          <div className="param-row">
            <NumberField
              spec={seedSpec}
              value={params[seedSpec.id] ?? seedSpec.default}
              onCommit={(v) => onChange(seedSpec.id, v, true)}
              className="seed-field"
              id="seed-field"
            />
            <button type="button" data-testid="randomize" onClick={props.onRandomize}>
              Randomize
            </button>
          </div>
        </div>
      ) : null}

      <div className="panel-block panel-actions">
        {HISTORY_BUTTONS.map(({ id, label, title, keys }) => (
          <button
            key={id}
            type="button"
            data-testid={id}
            title={title}
            aria-keyshortcuts={keys}
            disabled={id === 'undo' ? !props.canUndo : !props.canRedo}
            onClick={id === 'undo' ? props.onUndo : props.onRedo}
          >
            {label}
          </button>
        ))}
        <button type="button" data-testid="reset" onClick={props.onReset}>
          Reset to defaults
        </button>
      </div>

      <ParamGroups
        groups={groups}
        params={params}
        onChange={onChange}
        open={(_, index) => index < 3}
        extras={props.extras}
      />
    </aside>
  );
}
