/** Overlay with the current tree's vertex/triangle counts, generation and round-trip time, hash. */
import { useSyncExternalStore } from 'react';
import type { StatsStore } from '../app/statsStore';

const integer = new Intl.NumberFormat('en-US');

/**
 * Stats box over the viewer; shows dashes until the first tree arrives. It reads its own store
 * so that a new tree re-renders only this box.
 */
export function StatsOverlay({ store }: { store: StatsStore }) {
  const { stats, busy } = useSyncExternalStore(store.subscribe, store.get);
  return (
    <div className="stats" aria-live="polite">
      <dl>
        <dt>Vertices</dt>
        <dd data-testid="stat-vertices">{stats ? integer.format(stats.vertices) : '–'}</dd>
        <dt>Triangles</dt>
        <dd data-testid="stat-triangles">{stats ? integer.format(stats.triangles) : '–'}</dd>
        <dt>Generated in</dt>
        <dd data-testid="stat-ms">{stats ? `${stats.total_ms.toFixed(1)} ms` : '–'}</dd>
        <dt title="Request to geometry on screen: generation in the worker, transfer, BufferGeometry">
          Round trip
        </dt>
        <dd
          data-testid="stat-roundtrip"
          data-roundtrip-ms={stats?.roundTripMs ?? ''}
          data-draw-ms={stats?.drawMs ?? ''}
        >
          {stats?.roundTripMs != null ? `${stats.roundTripMs.toFixed(1)} ms` : '–'}
        </dd>
        <dt>Hash</dt>
        <dd
          data-testid="stat-hash"
          className="hash"
          title={stats?.preview ? 'A preview has no hash: the full tree follows' : undefined}
        >
          {stats ? stats.hash || (stats.preview ? 'preview' : '…') : '–'}
        </dd>
      </dl>
      {stats?.preview ? (
        <div className="preview-badge" data-testid="stat-preview" role="status">
          preview
        </div>
      ) : null}
      {busy ? (
        <div className="busy" data-testid="busy" role="status">
          <span className="spinner" aria-hidden="true" /> Generating…
        </div>
      ) : null}
    </div>
  );
}
