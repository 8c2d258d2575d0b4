/** One registry-generated control: slider + number (float/int), checkbox (bool) or select (enum). */
import { memo } from 'react';
import { type ParamSpec, snapToStep } from 'sylva-trees/core';
import { NumberField } from './NumberField';

interface Props {
  spec: ParamSpec;
  value: number;
  /** `interactive`: a step of a drag or of typing (the full tree follows when it settles). */
  onChange: (id: ParamSpec['id'], value: number, interactive?: boolean) => void;
}

/**
 * Renders the control matching `spec.kind`; the tooltip is the param's description. Memoised:
 * while one slider is dragged only that control re-renders (with a stable `onChange`).
 */
export const ParamControl = memo(function ParamControl({ spec, value, onChange }: Props) {
  const inputId = `param-${spec.id}`;
  const label = (
    <label htmlFor={inputId} className="param-label">
      {spec.label}
      {spec.unit ? <span className="unit"> ({spec.unit})</span> : null}
    </label>
  );
  if (spec.kind === 'bool') {
    return (
      <div className="param param-bool" title={spec.description}>
        <input
          id={inputId}
          type="checkbox"
          data-param-id={spec.id}
          data-testid={`param-check-${spec.id}`}
          checked={value !== 0}
          onChange={(e) => onChange(spec.id, e.currentTarget.checked ? 1 : 0, true)}
        />
        {label}
      </div>
    );
  }
  if (spec.kind === 'enum') {
    return (
      <div className="param" title={spec.description}>
        {label}
        <select
          id={inputId}
          data-param-id={spec.id}
          data-testid={`param-select-${spec.id}`}
          value={value}
          onChange={(e) => onChange(spec.id, Number(e.currentTarget.value), true)}
        >
          {(spec.options ?? []).map((option, index) => (
            <option key={option} value={index}>
              {option}
            </option>
          ))}
        </select>
      </div>
    );
  }
  return (
    <div className="param" title={spec.description}>
      {label}
      <div className="param-row">
        {/* React's onChange on a range input fires on every native `input` event (while dragging). */}
        <input
          id={inputId}
          type="range"
          data-param-id={spec.id}
          data-testid={`param-range-${spec.id}`}
          min={spec.min}
          max={spec.max}
          step={spec.step > 0 ? spec.step : 'any'}
          value={value}
          onChange={(e) => onChange(spec.id, snapToStep(spec, e.currentTarget.valueAsNumber), true)}
        />
        <NumberField spec={spec} value={value} onCommit={(v) => onChange(spec.id, v, true)} />
      </div>
    </div>
  );
});
