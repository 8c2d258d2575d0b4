/** Growth section controls: add spheres, boxes and cylinders, pick one for the gizmo, remove. */
import { useState } from 'react';
import { MAX_VOLUMES, type VolumeGroup, type VolumeKind } from 'sylva-trees/core';
import type { GrowthEditor } from '../app/useGrowthEditor';

const KINDS: VolumeKind[] = ['sphere', 'box', 'cylinder'];
const GROUPS: VolumeGroup[] = ['crown', 'shadow', 'exclusion'];
const MODES: ['translate' | 'scale', string][] = [
  ['translate', 'Move'],
  ['scale', 'Scale'],
];

interface Props {
  editor: GrowthEditor;
}

/** See the module comment. */
export function GrowthTools({ editor }: Props) {
  const [group, setGroup] = useState<VolumeGroup>('crown');
  const full = editor.volumes.length >= MAX_VOLUMES;
  return (
    <div className="growth-tools" data-testid="growth-tools">
      <div className="param-row">
        <label htmlFor="volume-group" className="param-label">
          New primitive
        </label>
        <select
          id="volume-group"
          data-testid="volume-group"
          value={group}
          onChange={(e) => setGroup(e.currentTarget.value as VolumeGroup)}
        >
          {GROUPS.map((g) => (
            <option key={g} value={g}>
              {g}
            </option>
          ))}
        </select>
      </div>
      <div className="param-row">
        {KINDS.map((kind) => (
          <button
            key={kind}
            type="button"
            data-testid={`add-${kind}`}
            disabled={full}
            title={`Add a ${kind} to the ${group} group; drag it with the gizmo`}
            onClick={() => editor.add(kind, group)}
          >
            Add {kind}
          </button>
        ))}
      </div>
      {editor.volumes.length > 0 ? (
        <>
          <div className="param-row" role="group" aria-label="Gizmo mode">
            {MODES.map(([mode, label]) => (
              <button
                key={mode}
                type="button"
                data-testid={`gizmo-${mode}`}
                aria-pressed={editor.mode === mode}
                onClick={() => editor.setMode(mode)}
              >
                {label}
              </button>
            ))}
          </div>
          <ul className="volume-list" data-testid="volume-list">
            {editor.volumes.map((v, i) => (
              <li key={i} className={i === editor.selected ? 'selected' : undefined}>
                <button
                  type="button"
                  aria-pressed={i === editor.selected}
                  onClick={() => editor.select(i === editor.selected ? null : i)}
                  title="Show the drag gizmo on this primitive"
                >
                  {v.kind} {i + 1}
                </button>
                <select
                  aria-label={`Group of ${v.kind} ${i + 1}`}
                  value={v.group}
                  onChange={(e) => editor.setGroup(i, e.currentTarget.value as VolumeGroup)}
                >
                  {GROUPS.map((g) => (
                    <option key={g} value={g}>
                      {g}
                    </option>
                  ))}
                </select>
                <button type="button" title="Remove" onClick={() => editor.remove(i)}>
                  ×
                </button>
              </li>
            ))}
          </ul>
        </>
      ) : null}
    </div>
  );
}

/** Progress bar and Cancel button shown while a growth is running. */
export function GrowthProgress({
  progress,
  onCancel,
}: {
  progress: number | null;
  onCancel: () => void;
}) {
  if (progress === null) return null;
  const percent = Math.round(progress * 100);
  return (
    <div className="growth-progress" data-testid="growth-progress">
      <progress max={100} value={percent} aria-label="Growth progress" />
      <span>{percent} %</span>
      <button type="button" data-testid="cancel-generation" onClick={onCancel}>
        Cancel
      </button>
    </div>
  );
}
