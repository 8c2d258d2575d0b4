/** Overlay with the current tree's vertex/triangle counts, generation and round-trip time, hash. */
import type { TreeStats } from '../app/useGenerator';

const integer = new Intl.NumberFormat('en-US');

/** Stats box over the viewer; shows dashes until the first tree arrives. */
export function StatsOverlay({ stats, busy }: { stats: TreeStats | null; busy: boolean }) {
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
        <dd data-testid="stat-hash" className="hash">
          {stats ? stats.hash : '–'}
        </dd>
      </dl>
      {busy ? (
        <div className="busy" data-testid="busy" role="status">
          <span className="spinner" aria-hidden="true" /> Generating…
        </div>
      ) : null}
    </div>
  );
}
