/**
 * Starts the generator worker next to this module, written as `new Worker(new URL('…',
 * import.meta.url), …)` so that bundlers follow it (see `urls.ts`; the package build rewrites the
 * source path to `./worker.js`).
 */

/** Starts the generator worker (`worker/worker.ts`) as an ES module worker named `name`. */
export function startGeneratorWorker(name = ''): Worker {
  // Vite reads `type` statically: the name comes after it.
  return new Worker(new URL('../worker/worker.ts', import.meta.url), { type: 'module', name });
}
