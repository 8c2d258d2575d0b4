/**
 * The leaf inspector: the core's 2D SVG of the current leaf (outline, margin, triangulation,
 * auxin sources, veins with pipe widths), a step slider replaying venation growth, an
 * Open/Closed switch, a leaf preset picker, every leaf parameter, and Export SVG.
 *
 * The SVG text comes from the worker; it is parsed with DOMParser as `image/svg+xml` and the
 * resulting `<svg>` element is adopted into the page (no innerHTML; the SVG has no scripts or
 * style attributes, so the CSP holds).
 */
import { useEffect, useMemo, useRef, useState, useSyncExternalStore, type RefObject } from 'react';
import {
  groupParams,
  type LeafInspection,
  normalizeValue,
  type Params,
  type ParamSpec,
  type LeafPreset,
  type SylvaError,
} from 'sylva-trees/core';
import { createModuleWorker } from '../createWorker';
import { downloadBlob } from '../export/download';
import { LeafClient } from '../leaf/leafClient';
import { applyMonthTint, monthTint } from '../leaf/monthTint';
import { ParamGroups, PresetOptions } from './ParamGroups';

/** Registry groups the inspector edits. */
export const LEAF_GROUPS = ['Leaf', 'Leaf Veins', 'Leaf Surface'];

interface Props {
  registry: readonly ParamSpec[];
  params: Params;
  onChange: (id: ParamSpec['id'], value: number, interactive?: boolean) => void;
  /** Applies several values at once (a leaf preset). */
  onChangeMany: (values: Params) => void;
}

/** Only the leaf parameters (the leaf does not depend on the others). */
function leafParams(registry: readonly ParamSpec[], params: Params): Params {
  const out: Params = {};
  for (const spec of registry) {
    const v = params[spec.id];
    if (LEAF_GROUPS.includes(spec.group) && v !== undefined) out[spec.id] = v;
  }
  return out;
}

/** Saves the SVG `text` as `name`. */
function downloadSvg(text: string, name: string): void {
  downloadBlob(new Blob([text], { type: 'image/svg+xml' }), name);
}

/** What the inspector shows: the leaf drawing from its own worker, errors, the leaf presets. */
interface LeafDrawing {
  leaf: LeafInspection | null;
  error: SylvaError | null;
  presets: LeafPreset[];
  /** The element the SVG is adopted into. */
  viewRef: RefObject<HTMLDivElement | null>;
}

/** Draws the leaf of `params` at growth `step` in the inspector's worker (latest request wins). */
function useLeafDrawing(
  registry: readonly ParamSpec[],
  params: Params,
  step: number,
  triangulation: boolean,
): LeafDrawing {
  const clientRef = useRef<LeafClient | null>(null);
  const viewRef = useRef<HTMLDivElement | null>(null);
  // The Season's colour of the tree's leaves (leaf/monthTint.ts).
  const tint = useSyncExternalStore(monthTint.subscribe, monthTint.get);
  const [leaf, setLeaf] = useState<LeafInspection | null>(null);
  const [error, setError] = useState<SylvaError | null>(null);
  const [presets, setPresets] = useState<LeafPreset[]>([]);
  const [ready, setReady] = useState(false);

  useEffect(() => {
    const client = new LeafClient(createModuleWorker, {
      onLeaf: (next) => {
        setLeaf(next);
        setError(null);
      },
      onError: setError,
      onPresets: (list) => {
        setPresets(list);
        setReady(true);
      },
    });
    clientRef.current = client;
    return () => {
      client.dispose();
      clientRef.current = null;
    };
  }, []);

  const leafValues = useMemo(() => leafParams(registry, params), [registry, params]);
  const key = JSON.stringify(leafValues);
  useEffect(() => {
    if (ready) clientRef.current?.request(JSON.parse(key) as Params, step, triangulation);
  }, [key, step, triangulation, ready]);

  // Adopt the parsed SVG element into the view.
  useEffect(() => {
    const view = viewRef.current;
    if (!view || !leaf) return;
    const doc = new DOMParser().parseFromString(leaf.svg, 'image/svg+xml');
    const svg = doc.documentElement;
    if (svg.nodeName !== 'svg') return;
    svg.setAttribute('data-testid', 'leaf-svg');
    svg.removeAttribute('width');
    svg.removeAttribute('height');
    const shown = document.importNode(svg, true) as unknown as SVGSVGElement;
    applyMonthTint(shown, tint);
    view.replaceChildren(shown);
  }, [leaf, tint]);

  return { leaf, error, presets, viewRef };
}

/** The inspector panel. */
export function LeafInspector({ registry, params, onChange, onChangeMany }: Props) {
  const [step, setStep] = useState(-1);
  const [triangulation, setTriangulation] = useState(false);
  const { leaf, error, presets, viewRef } = useLeafDrawing(registry, params, step, triangulation);
  const specs = registry.filter((s) => LEAF_GROUPS.includes(s.group));
  const groups = groupParams(specs);
  const venation = registry.find((s) => s.id === 'leaf_venation');
  const iterations = leaf?.iterations ?? 0;
  const shownStep = step < 0 ? iterations : Math.min(step, iterations);

  const applyLeafPreset = (name: string) => {
    const preset = presets.find((p) => p.name === name);
    if (!preset) return;
    const values: Params = {};
    for (const spec of specs) {
      const v = preset.values[spec.id];
      values[spec.id] = v === undefined ? spec.default : normalizeValue(spec, v);
    }
    setStep(-1);
    onChangeMany(values);
  };

  return (
    <aside
      className="panel leaf-inspector"
      aria-label="Leaf inspector"
      data-testid="leaf-inspector"
    >
      <div className="leaf-view" ref={viewRef} />
      <div className="leaf-counts" data-testid="leaf-counts">
        {leaf
          ? `${leaf.segments} vein segments · ${leaf.nodes} nodes · ${leaf.links} loops · ${leaf.auxins} sources · ${leaf.triangles} triangles`
          : 'Growing the leaf…'}
      </div>
      {error ? (
        <div className="leaf-error" role="alert">
          {error.message}
        </div>
      ) : null}
      <label className="row">
        Leaf preset
        <select
          data-testid="leaf-preset"
          defaultValue=""
          onChange={(e) => applyLeafPreset(e.currentTarget.value)}
        >
          <option value="" disabled>
            Choose…
          </option>
          <PresetOptions presets={presets} />
        </select>
      </label>
      <label className="row">
        Growth step {shownStep} of {iterations}
        <input
          type="range"
          data-testid="leaf-step"
          min={0}
          max={Math.max(iterations, 1)}
          step={1}
          value={shownStep}
          onChange={(e) => {
            const v = Number(e.currentTarget.value);
            setStep(v >= iterations ? -1 : v);
          }}
        />
      </label>
      <div className="row">
        {venation ? (
          <span role="group" aria-label="Venation">
            {['Open', 'Closed'].map((label) => {
              const index = venation.options?.indexOf(label) ?? -1;
              return (
                <button
                  key={label}
                  type="button"
                  data-testid={`leaf-${label.toLowerCase()}`}
                  aria-pressed={params.leaf_venation === index}
                  onClick={() => onChange('leaf_venation', index)}
                >
                  {label}
                </button>
              );
            })}
          </span>
        ) : null}
        <label>
          <input
            type="checkbox"
            data-testid="leaf-triangulation"
            checked={triangulation}
            onChange={(e) => setTriangulation(e.currentTarget.checked)}
          />{' '}
          Triangulation
        </label>
        <button
          type="button"
          data-testid="leaf-export"
          disabled={!leaf}
          onClick={() => leaf && downloadSvg(leaf.svg, `sylva-leaf-${leaf.hash}.svg`)}
        >
          Export SVG
        </button>
      </div>
      <ParamGroups
        groups={groups}
        params={params}
        onChange={onChange}
        open={(group) => group === 'Leaf'}
      />
    </aside>
  );
}
