/**
 * Compact wind panel over the viewer: on/off, pause, and (expanded) strength, direction and
 * gusts. Wind settings belong to the viewer, not to the tree: they are saved in localStorage
 * (not in the share URL) and never regenerate the tree. Also adds the wind parts of the debug
 * hook (`setWindTime`, `setWind`, `pauseWind`, `wind`, `frameHash`, `barkTexture`).
 */
import { useCallback, useEffect, useId, useRef, useState, type RefObject } from 'react';
import { installDebugHook } from '../app/debugHook';
import { browserStorage } from '../app/persistence';
import type { TreeViewer } from '../viewer/TreeViewer';
import {
  loadWind,
  sanitizeWind,
  saveWind,
  WIND_LIMITS,
  type WindSettings,
} from 'sylva-trees/viewer';
import './WindControls.css';

type NumericKey = 'strength' | 'direction' | 'gust';

const SLIDERS: { key: NumericKey; label: string; format: (v: number) => string }[] = [
  { key: 'strength', label: 'Strength', format: (v) => v.toFixed(2) },
  { key: 'direction', label: 'Direction', format: (v) => `${Math.round(v)}°` },
  { key: 'gust', label: 'Gusts', format: (v) => v.toFixed(2) },
];

/** The wind panel; applies its settings to the viewer in `viewerRef`. */
export function WindControls({ viewerRef }: { viewerRef: RefObject<TreeViewer | null> }) {
  const [settings, setSettings] = useState<WindSettings>(() => loadWind(browserStorage()));
  const [open, setOpen] = useState(false);
  const settingsRef = useRef(settings);
  const baseId = useId();

  // Applied synchronously (the debug hook renders right after) and kept in React state.
  const update = useCallback(
    (change: Partial<WindSettings>) => {
      const next = sanitizeWind(change, settingsRef.current);
      settingsRef.current = next;
      viewerRef.current?.wind.set(next);
      setSettings(next);
    },
    [viewerRef],
  );

  useEffect(() => {
    viewerRef.current?.wind.set(settings);
    saveWind(browserStorage(), settings);
  }, [settings, viewerRef]);

  useEffect(
    () =>
      installDebugHook({
        setWindTime: (seconds) => viewerRef.current?.wind.setTime(seconds),
        setWind: (change) => update(change),
        pauseWind: (paused) => update({ paused }),
        wind: () => ({
          ...settingsRef.current,
          time: viewerRef.current?.wind.clock.time ?? 0,
          vertexData: viewerRef.current?.wind.hasVertexData ?? false,
        }),
        frameHash: () => viewerRef.current?.frameHash() ?? null,
        barkTexture: () => viewerRef.current?.barkTexture ?? null,
      }),
    [update, viewerRef],
  );

  const panelId = `${baseId}-panel`;
  return (
    <section className="wind-controls" aria-label="Wind" data-testid="wind-controls">
      <div className="wind-row">
        <label className="wind-toggle">
          <input
            type="checkbox"
            data-testid="wind-enabled"
            checked={settings.enabled}
            onChange={(e) => update({ enabled: e.currentTarget.checked })}
          />
          Wind
        </label>
        <button
          type="button"
          data-testid="wind-pause"
          aria-pressed={settings.paused}
          disabled={!settings.enabled}
          title={settings.paused ? 'Let the wind blow again' : 'Freeze the tree in its pose'}
          onClick={() => update({ paused: !settings.paused })}
        >
          {settings.paused ? 'Resume' : 'Pause'}
        </button>
        <button
          type="button"
          className="wind-more"
          data-testid="wind-more"
          aria-expanded={open}
          aria-controls={panelId}
          aria-label="Wind settings"
          onClick={() => setOpen(!open)}
        >
          More
        </button>
      </div>
      {open ? (
        <div id={panelId} className="wind-sliders">
          {SLIDERS.map(({ key, label, format }) => {
            const id = `${baseId}-${key}`;
            const limits = WIND_LIMITS[key];
            return (
              <div className="wind-slider" key={key}>
                <label htmlFor={id}>
                  {label}
                  {key === 'direction' ? (
                    <span
                      className="wind-arrow"
                      aria-hidden="true"
                      style={{ transform: `rotate(${settings.direction}deg)` }}
                    >
                      →
                    </span>
                  ) : null}
                </label>
                <input
                  id={id}
                  type="range"
                  data-testid={`wind-${key}`}
                  min={limits.min}
                  max={limits.max}
                  step={limits.step}
                  value={settings[key]}
                  disabled={!settings.enabled}
                  onChange={(e) => update({ [key]: e.currentTarget.valueAsNumber })}
                />
                <output htmlFor={id} data-testid={`wind-${key}-value`}>
                  {format(settings[key])}
                </output>
              </div>
            );
          })}
        </div>
      ) : null}
    </section>
  );
}
