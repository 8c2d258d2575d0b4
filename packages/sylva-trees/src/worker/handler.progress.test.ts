/** Growth through the real wasm and the worker handler: progress messages, markers, volumes. */
import { describe, expect, it } from 'vitest';
import { loadWasm } from '../testing/realWasm';
import { createHandler } from './handler';
import type { WorkerRequest, WorkerResponse } from './protocol';

function run(request: WorkerRequest) {
  const sent: WorkerResponse[] = [];
  const now = (task: () => void) => {
    task();
    return () => undefined;
  };
  createHandler(loadWasm(), (message) => sent.push(message), { defer: now })(request);
  return sent;
}

const GROW = { growth_mode: 1, iterations: 300, markers: 800, extra_markers: 300 };

describe('growth through the worker handler', () => {
  it('posts increasing progress for the request before its result, with the markers', () => {
    const sent = run({ type: 'generate', id: 7, params: GROW });
    const progress = sent.filter((m) => m.type === 'progress');
    expect(progress.length).toBeGreaterThan(3);
    expect(progress.length).toBeLessThanOrEqual(51);
    const fractions = progress.map((m) => (m.type === 'progress' ? m.fraction : -1));
    expect(fractions.every((f, i) => f > 0 && f <= 1 && (i === 0 || f > fractions[i - 1]!))).toBe(
      true,
    );
    expect(progress.every((m) => m.type === 'progress' && m.id === 7)).toBe(true);
    const last = sent.findLast((m) => m.type === 'result');
    if (last?.type !== 'result') throw new Error('expected a result');
    expect(sent.at(-1)?.type).toBe('hash');
    expect(last.markers?.length).toBeGreaterThan(300);
    expect((last.markers?.length ?? 0) % 3).toBe(0);
  });

  it('sends volumes to the core: a crown sphere changes the tree, a bad one names the field', () => {
    const hash = (sent: WorkerResponse[]) => {
      const last = sent[sent.length - 1];
      if (last?.type !== 'hash') throw new Error(JSON.stringify(last));
      return last.hash;
    };
    const plain = hash(run({ type: 'generate', id: 1, params: { ...GROW, crown_volume: 2 } }));
    const sphere = {
      kind: 'sphere',
      group: 'crown',
      centre: [1, 6, 0],
      size: [2.5, 2.5, 2.5],
    } as const;
    const withSphere = run({
      type: 'generate',
      id: 2,
      params: { ...GROW, crown_volume: 2 },
      volumes: [{ ...sphere, centre: [1, 6, 0], size: [2.5, 2.5, 2.5] }],
    });
    expect(hash(withSphere)).not.toBe(plain);
    const bad = run({
      type: 'generate',
      id: 3,
      params: GROW,
      volumes: [{ ...sphere, centre: [1, 6, 0], size: [0, 0, 0] }],
    });
    expect(bad[bad.length - 1]).toMatchObject({
      type: 'error',
      id: 3,
      error: { kind: 'invalid_param', param: 'volumes[0].radius' },
    });
  });
});
