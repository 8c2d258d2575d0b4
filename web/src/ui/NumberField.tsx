/** Numeric input bound to a param: keeps the typed text while editing, commits valid values. */
import { useState } from 'react';
import { displayValue, snapToStep } from '../core/params';
import type { ParamSpec } from '../core/types';

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
  const [draft, setDraft] = useState<string | null>(null);
  const text = draft ?? displayValue(spec, value);
  const invalid = draft !== null && parseInRange(spec, draft) === null;
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
        setDraft(next);
        const parsed = parseInRange(spec, next);
        if (parsed !== null && parsed !== value) onCommit(parsed);
      }}
      onBlur={() => setDraft(null)}
      onKeyDown={(e) => {
        if (e.key === 'Enter') setDraft(null);
      }}
    />
  );
}
