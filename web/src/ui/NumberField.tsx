/** Numeric input bound to a param: keeps the typed text while editing, commits valid values. */
import { useState } from 'react';
import { displayValue, type ParamSpec, snapToStep } from 'sylva-trees/core';

interface Props {
  spec: ParamSpec;
  value: number;
  onCommit: (value: number) => void;
  className?: string;
  id?: string;
}

function parseInRange(spec: ParamSpec, text: string): number | null {
  if (text.trim() === '') return null;
  const n = Number(text);
  if (!Number.isFinite(n) || n < spec.min || n > spec.max) return null;
  return snapToStep(spec, n);
}

/** A `<input type="number">` that never fights the user's partial input. */
export function NumberField({ spec, value, onCommit, className, id }: Props) {
  // The text being typed, with the value it belongs to: when the value changes from elsewhere
  // (undo, a preset, the slider), the stale draft is dropped and the new value shown.
  const [draft, setDraft] = useState<{ text: string; value: number } | null>(null);
  const current = draft !== null && Object.is(draft.value, value) ? draft.text : null;
  const text = current ?? displayValue(spec, value);
  const invalid = current !== null && parseInRange(spec, current) === null;
  return (
    <input
      type="number"
      id={id}
      className={className ?? 'param-number'}
      data-param-id={spec.id}
      data-testid={`param-number-${spec.id}`}
      aria-label={`${spec.label} value`}
      aria-invalid={invalid}
      min={spec.min}
      max={spec.max}
      step={spec.step > 0 ? spec.step : 'any'}
      value={text}
      onChange={(e) => {
        const next = e.currentTarget.value;
        const parsed = parseInRange(spec, next);
        setDraft({ text: next, value: parsed ?? value });
        if (parsed !== null && parsed !== value) onCommit(parsed);
      }}
      onBlur={() => setDraft(null)}
      onKeyDown={(e) => {
        if (e.key === 'Enter') setDraft(null);
      }}
    />
  );
}
