/**
 * Test helper: a generator-worker factory whose workers are fakes, recording what a client posts
 * and letting the test answer (`emit`, or `ready()` from the newest worker).
 */
import type { GeneratorWorkerFactory, WorkerRequest, WorkerResponse } from 'sylva-trees/worker';

/** One fake worker: the requests posted to it, and a way to answer. */
export interface FakeWorker {
  posted: WorkerRequest[];
  emit: (response: WorkerResponse) => void;
}

/** A factory of fake workers, the workers it made, and `ready()` for the newest one. */
export function fakeWorkers(): {
  factory: GeneratorWorkerFactory;
  workers: FakeWorker[];
  ready: () => void;
} {
  const workers: FakeWorker[] = [];
  const factory: GeneratorWorkerFactory = (onMessage) => {
    const fake = { posted: [] as WorkerRequest[], emit: onMessage };
    workers.push(fake);
    return { post: (r) => fake.posted.push(r), terminate: () => undefined };
  };
  const ready = (): void =>
    workers.at(-1)?.emit({ type: 'ready', registry: [], presets: [], version: 't' });
  return { factory, workers, ready };
}
