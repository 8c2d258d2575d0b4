/**
 * The generator worker for `<sylva-tree>` on any page. The worker script and the wasm live next
 * to `sylva-tree.js` (resolved from its own URL, so the element works from any host and path).
 * A worker must be same-origin: from another origin a tiny module worker made from a blob: URL
 * imports the real one (the host then needs CORS, and the page's CSP must allow blob: workers).
 */
import workerUrl from 'sylva-trees/worker-script?worker&url';
import { adaptWorker, type WorkerHandle } from 'sylva-trees/worker';

/** Absolute URL of the built worker script. */
export function generatorWorkerUrl(): URL {
  return new URL(workerUrl, import.meta.url);
}

/** Starts a module worker from `url`, through a blob: shim when it is on another origin. */
export function startModuleWorker(url: URL, pageOrigin: string): Worker {
  if (url.origin === pageOrigin) return new Worker(url, { type: 'module' });
  const shim = new Blob([`import ${JSON.stringify(url.href)};\n`], { type: 'text/javascript' });
  const shimUrl = URL.createObjectURL(shim);
  const worker = new Worker(shimUrl, { type: 'module' });
  // The shim is fetched when the worker starts; keep its URL until then.
  const revoke = (): void => URL.revokeObjectURL(shimUrl);
  worker.addEventListener('message', revoke, { once: true });
  worker.addEventListener('error', revoke, { once: true });
  return worker;
}

/** Worker factory for the scheduler (like `createModuleWorker`, cross-origin capable). */
export function elementWorkerFactory<Req, Res>(
  onMessage: (response: Res) => void,
  onError: (message: string) => void,
): WorkerHandle<Req> {
  let worker: Worker;
  try {
    worker = startModuleWorker(generatorWorkerUrl(), window.location.origin);
  } catch (thrown) {
    const message = thrown instanceof Error ? thrown.message : String(thrown);
    // Reported after the scheduler has stored the handle, as a failed start.
    queueMicrotask(() => onError(`the generator worker could not start (${message})`));
    return { post: () => undefined, terminate: () => undefined };
  }
  return adaptWorker(
    worker,
    onMessage,
    onError,
    undefined,
    'the generator worker failed to load (cross-origin use needs CORS on the Sylva host ' +
      'and worker-src blob: in the page CSP)',
  );
}
