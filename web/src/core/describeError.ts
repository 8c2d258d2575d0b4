/** Human-readable text of a generator error (the app's banner, the embed's status line). */
import type { ParamSpec, SylvaError } from 'sylva-trees/core';

/** `crashed` opens the text of a panic (the app adds that the worker was restarted). */
export function describeError(
  error: SylvaError,
  registry: readonly ParamSpec[],
  crashed = 'The generator crashed',
): string {
  if (error.kind === 'panic') return `${crashed}: ${error.message}`;
  if (error.param) {
    const spec = registry.find((s) => s.id === error.param);
    const name = spec ? `${spec.label} (${error.param})` : error.param;
    return `Invalid parameter ${name}: ${error.message}`;
  }
  if (error.kind === 'budget') return `Tree too large: ${error.message}`;
  return error.message;
}
