/**
 * The side of the app: the Tree / Leaf tabs and the panel under them (the parameter panel with
 * the growth tools, or the leaf inspector). Every edit goes to the editor's reducer.
 */
import { useCallback, useState } from 'react';
import {
  applyPreset,
  defaultParams,
  type Params,
  type ParamSpec,
  type Preset,
  randomSeed,
} from 'sylva-trees/core';
import { AgePlayer } from '../ui/AgePlayer';
import { GrowthTools } from '../ui/GrowthTools';
import { LeafInspector } from '../ui/LeafInspector';
import { ParamPanel } from '../ui/ParamPanel';
import type { Editor } from './useEditor';
import type { GrowthEditor } from './useGrowthEditor';

interface Props {
  registry: readonly ParamSpec[];
  presets: readonly Preset[];
  /** Null while the generator loads: the tabs and an empty panel keep their place. */
  params: Params | null;
  /** The core's version and the threads a generation uses (`ReadyInfo`); null while it loads. */
  core: { version: string; threads: number } | null;
  activePreset: Preset['name'] | null;
  editor: Editor;
  growth: GrowthEditor;
}

/** The tab buttons and the panel of the chosen tab. */
export function SidePanel({
  registry,
  presets,
  params,
  core,
  activePreset,
  editor,
  growth,
}: Props) {
  // Side panel: the tree parameters or the leaf inspector.
  const [tab, setTab] = useState<'tree' | 'leaf'>('tree');
  const { change, paramsRef } = editor;
  /** A control changed a value; `interactive` while it is dragged or typed into. */
  const onChange = useCallback(
    (id: ParamSpec['id'], value: number, interactive = false) => {
      const current = paramsRef.current;
      if (current) change({ params: { ...current, [id]: value }, key: id }, interactive);
    },
    [change, paramsRef],
  );
  const onChangeMany = useCallback(
    (values: Params) => {
      const current = paramsRef.current;
      if (current) change({ params: { ...current, ...values }, key: null });
    },
    [change, paramsRef],
  );
  const loaded = params !== null && core !== null;
  return (
    <>
      {/* The tabs and the panel take their place from the start: the stage (and the canvas)
          keeps its size when the generator is ready, instead of a resize that waits for the
          GPU's first frames. */}
      <nav className="panel-tabs" aria-label="Panels">
        {(['tree', 'leaf'] as const).map((name) => (
          <button
            key={name}
            type="button"
            data-testid={`tab-${name}`}
            aria-pressed={tab === name}
            disabled={!loaded}
            onClick={() => setTab(name)}
          >
            {name === 'tree' ? 'Tree' : 'Leaf'}
          </button>
        ))}
      </nav>
      {!loaded ? <aside className="panel" aria-busy="true" aria-label="Loading" /> : null}
      {loaded && tab === 'leaf' ? (
        <LeafInspector
          registry={registry}
          params={params}
          onChange={onChange}
          onChangeMany={onChangeMany}
        />
      ) : null}
      {loaded && tab === 'tree' ? (
        <ParamPanel
          registry={registry}
          presets={presets}
          params={params}
          activePreset={activePreset}
          version={core.version}
          threads={core.threads}
          canUndo={editor.canUndo}
          canRedo={editor.canRedo}
          onChange={onChange}
          onPreset={(name) => {
            const preset = presets.find((p) => p.name === name);
            if (preset) change({ params: applyPreset(registry, preset), key: null, frame: true });
          }}
          onRandomize={() => {
            const seedSpec = registry.find((s) => s.id === 'seed');
            const current = paramsRef.current ?? params;
            if (seedSpec) change({ params: { ...current, seed: randomSeed(seedSpec) }, key: null });
          }}
          onReset={() => change({ params: defaultParams(registry), key: null, frame: true })}
          onUndo={editor.undo}
          onRedo={editor.redo}
          extras={{
            Tree: <AgePlayer params={params} onChange={onChange} />,
            'Growth Volume': <GrowthTools editor={growth} />,
          }}
        />
      ) : null}
    </>
  );
}
