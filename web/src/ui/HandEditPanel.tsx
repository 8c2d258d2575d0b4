/**
 * "Shape by hand" over the 3D view: the tool buttons (Paint, Crown, Cut, Bend, with their
 * shortcuts), the brush of the Paint tool, the edit list (one row per edit: op, summary, whether
 * it resolved, delete), the share-link message when the list is too long for a link, and the
 * JSON export and import.
 */
import { useRef } from 'react';
import {
  DENSITY_RANGE,
  KILL_RANGE,
  MAX_EDITS,
  RADIUS_RANGE,
  SEGMENT_RANGE,
  summarizeEdit,
} from 'sylva-trees/core';
import type { HandEdits } from '../app/useHandEdits';
import type { Brush, EditTool } from '../viewer/HandEditTools';
import { downloadBlob, readTextFile } from '../export/download';
import './HandEditPanel.css';

/** Largest edit list file read (bytes): 65,536 points of text fit well inside. */
export const MAX_EDITS_FILE_BYTES = 8 * 1024 * 1024;

const TOOLS: { tool: EditTool; label: string; key: string; hint: string }[] = [
  {
    tool: 'paint',
    label: 'Paint',
    key: 'P',
    hint: 'Drag over or beside the tree: it grows into the stroke.',
  },
  {
    tool: 'crown',
    label: 'Crown',
    key: 'O',
    hint: 'Look from the side and draw the crown’s outline around the trunk.',
  },
  { tool: 'cut', label: 'Cut', key: 'C', hint: 'Click a branch: it is cut there.' },
  {
    tool: 'bend',
    label: 'Bend',
    key: 'B',
    hint: 'Drag a point of a branch to where it should go.',
  },
];

const BRUSH_FIELDS: {
  id: keyof Brush;
  label: string;
  unit: string;
  range: readonly [number, number];
  step: number;
}[] = [
  { id: 'radius', label: 'Radius', unit: 'm', range: RADIUS_RANGE, step: 0.05 },
  { id: 'density', label: 'Density', unit: '/m³', range: DENSITY_RANGE, step: 10 },
  { id: 'segment', label: 'Segment', unit: 'm', range: SEGMENT_RANGE, step: 0.01 },
  { id: 'kill', label: 'Kill distance', unit: 'm', range: KILL_RANGE, step: 0.01 },
];

/** The brush's number fields (a value outside its range is clamped). */
function BrushFields({ brush, onChange }: { brush: Brush; onChange: (b: Brush) => void }) {
  return (
    <div className="hand-brush" data-testid="hand-brush">
      {BRUSH_FIELDS.map(({ id, label, unit, range, step }) => (
        <label key={id}>
          <span>
            {label} ({unit})
          </span>
          <input
            type="number"
            data-testid={`brush-${id}`}
            min={range[0]}
            max={range[1]}
            step={step}
            value={brush[id]}
            onChange={(e) => {
              const v = e.currentTarget.valueAsNumber;
              if (!Number.isFinite(v)) return;
              const value = Math.min(range[1], Math.max(range[0], v));
              const next = { ...brush, [id]: value };
              // The kill distance is at least the segment length (the core's rule).
              if (next.kill < next.segment) next.kill = next.segment;
              onChange(next);
            }}
          />
        </label>
      ))}
    </div>
  );
}

/** See the module comment. */
export function HandEditPanel({ hand }: { hand: HandEdits }) {
  const fileRef = useRef<HTMLInputElement>(null);
  const active = TOOLS.find((t) => t.tool === hand.tool);
  return (
    <div className="hand-edits" data-testid="hand-edits">
      <div className="hand-tools" role="toolbar" aria-label="Shape by hand">
        <span className="hand-title">Shape</span>
        {TOOLS.map(({ tool, label, key, hint }) => (
          <button
            key={tool}
            type="button"
            data-testid={`tool-${tool}`}
            aria-pressed={hand.tool === tool}
            aria-keyshortcuts={key}
            title={`${label} (${key}): ${hint}`}
            onClick={() => hand.setTool(hand.tool === tool ? null : tool)}
          >
            {label}
          </button>
        ))}
      </div>
      {active ? <p className="hand-hint">{active.hint} Esc: stop.</p> : null}
      {hand.tool === 'paint' ? <BrushFields brush={hand.brush} onChange={hand.setBrush} /> : null}
      {hand.edits.length > 0 ? (
        <ol className="edit-list" data-testid="edit-list">
          {hand.edits.map((edit, i) => {
            const report = hand.reports[i];
            const unresolved = report?.resolved === false;
            return (
              <li key={i} className={unresolved ? 'unresolved' : undefined} data-testid="edit-row">
                <span className="edit-op">{edit.op}</span>
                <span className="edit-summary">{summarizeEdit(edit)}</span>
                {unresolved ? (
                  <span
                    className="edit-unresolved"
                    data-testid="edit-unresolved"
                    title={report.why}
                  >
                    unresolved{report.why ? `: ${report.why}` : ''}
                  </span>
                ) : null}
                {report?.pending_year !== undefined ? (
                  <span
                    className="edit-pending"
                    data-testid="edit-pending"
                    title="The tree is younger than this cut: the branch is whole until then"
                  >
                    in year {report.pending_year}
                  </span>
                ) : null}
                <button
                  type="button"
                  aria-label={`Delete edit ${i + 1} (${edit.op})`}
                  title="Delete this edit"
                  onClick={() => hand.remove(i)}
                >
                  ×
                </button>
              </li>
            );
          })}
        </ol>
      ) : null}
      {hand.linkNotice ? (
        <p className="hand-link-notice" data-testid="edits-link-notice" role="status">
          {hand.linkNotice}
        </p>
      ) : null}
      <div className="hand-files">
        <button
          type="button"
          data-testid="export-edits"
          disabled={hand.edits.length === 0}
          title="Download the edit list as sylva-edits.json"
          onClick={() =>
            downloadBlob(
              new Blob([hand.exportText()], { type: 'application/json' }),
              'sylva-edits.json',
            )
          }
        >
          Export edits…
        </button>
        <button
          type="button"
          data-testid="import-edits"
          title={`Read an edit list (sylva-edits.json, at most ${MAX_EDITS} edits); it replaces the current one`}
          onClick={() => fileRef.current?.click()}
        >
          Import edits…
        </button>
        {hand.edits.length > 0 ? (
          <button type="button" data-testid="clear-edits" onClick={hand.clear}>
            Clear
          </button>
        ) : null}
      </div>
      <input
        ref={fileRef}
        type="file"
        accept=".json,application/json"
        hidden
        data-testid="edits-file-input"
        onChange={(e) => {
          const file = e.currentTarget.files?.[0];
          e.currentTarget.value = '';
          if (!file) return;
          readTextFile(file, MAX_EDITS_FILE_BYTES).then(hand.importText, (error: unknown) =>
            hand.importFailed(error instanceof Error ? error.message : String(error)),
          );
        }}
      />
    </div>
  );
}
