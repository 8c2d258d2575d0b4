/** Worker handler fault paths over a fake wasm API: traps other than a panic, OOM, hangs. */
import { describe, expect, it } from 'vitest';
import type { TreeMeta, WasmApi, WasmSession } from '../core/types';
import { createHandler, isTrap } from './handler';
import { debugHooks, type DebugRequest, type DebugResponse } from './debug';
import type { WorkerResponse } from './protocol';

const META = JSON.stringify({
  vertices: 1,
  triangles: 0,
  hash: '0123456789abcdef',
  bounds: { min: [0, 0, 0], max: [1, 1, 1] },
  groups: [],
  stage_ms: {},
  total_ms: 1,
  stems: 1,
  holes: 0,
  envelope: [],
  leaves: 0,
  leaf_hash: '0000000000000000',
  leaf_texture: null,
  bark_type: 0,
} satisfies TreeMeta);

interface FakeOptions {
  /** What `generate` throws (nothing: it returns a tree). */
  generateThrows?: unknown;
  /** What reading `positions()` throws. */
  positionsThrows?: unknown;
  /** What `take_panic` returns, or throws when it is an Error. */
  panic?: string | Error;
}

function fakeWasm(options: FakeOptions) {
  const state = { generated: 0 };
  const f32 = () => new Float32Array(0);
  const session: WasmSession = {
    update: () => {
      state.generated++;
      // eslint-disable-next-line @typescript-eslint/only-throw-error -- wasm throws JSON strings
      if (options.generateThrows !== undefined) throw options.generateThrows;
      return META;
    },
    hash: () => '0123456789abcdef',
    clear: () => undefined,
    positions: () => {
      // eslint-disable-next-line @typescript-eslint/only-throw-error -- wasm can throw any value
      if (options.positionsThrows !== undefined) throw options.positionsThrows;
      return new Float32Array(3);
    },
    normals: () => new Float32Array([0, 1, 0]),
    uvs: () => new Float32Array(2),
    indices: () => new Uint32Array(0),
    wind: f32,
    markers: f32,
    envelope_lines: f32,
    leaf_positions: f32,
    leaf_normals: f32,
    leaf_uvs: f32,
    leaf_indices: () => new Uint32Array(0),
    leaf_matrices: f32,
    leaf_colors: f32,
    leaf_texture: () => new Uint8Array(0),
    shade: () => new Uint8Array(0),
    free: () => undefined,
  };
  const wasm: WasmApi = {
    Session: class {
      constructor() {
        return session;
      }
    } as unknown as WasmApi['Session'],
    registry_json: () => '[]',
    presets_json: () => '[]',
    core_version: () => 'fake',
    generate: () => {
      throw new Error('the worker generates through its session');
    },
    take_panic: () => {
      if (options.panic instanceof Error) throw options.panic;
      return options.panic;
    },
  };
  return { wasm, state };
}

function run(options: FakeOptions) {
  const { wasm, state } = fakeWasm(options);
  const sent: WorkerResponse[] = [];
  const handle = createHandler(wasm, (message) => sent.push(message));
  return { handle, sent, state };
}

describe('worker handler fault handling', () => {
  it('a RuntimeError other than unreachable (memory fault) is fatal and kills the instance', () => {
    const { handle, sent, state } = run({
      generateThrows: new WebAssembly.RuntimeError('memory access out of bounds'),
    });
    handle({ type: 'generate', id: 1, params: {} });
    expect(sent).toHaveLength(1);
    const fatal = sent[0];
    expect(fatal?.type).toBe('fatal');
    if (fatal?.type !== 'fatal') return;
    expect(fatal.message).toContain('memory access out of bounds');
    // The instance is not used again: every later request is answered with the same fatal.
    handle({ type: 'generate', id: 2, params: {} });
    expect(sent[1]).toEqual(fatal);
    expect(state.generated).toBe(1);
  });

  it('an allocation failure (unreachable, no panic text) is reported as a possible OOM', () => {
    const { handle, sent } = run({
      generateThrows: new WebAssembly.RuntimeError('unreachable'),
      panic: undefined,
    });
    handle({ type: 'generate', id: 1, params: {} });
    const fatal = sent[0];
    expect(fatal?.type === 'fatal' && fatal.message).toMatch(/unreachable.*out of memory/);
  });

  it('a panic reports the recorded panic text, not the trap', () => {
    const { handle, sent } = run({
      generateThrows: new WebAssembly.RuntimeError('unreachable'),
      panic: 'panicked at skeleton.rs:1: boom',
    });
    handle({ type: 'generate', id: 1, params: {} });
    expect(sent[0]).toEqual({ type: 'fatal', message: 'panicked at skeleton.rs:1: boom' });
  });

  it('a trap while copying the buffers out is fatal', () => {
    const { handle, sent } = run({
      positionsThrows: new WebAssembly.RuntimeError('memory access out of bounds'),
    });
    handle({ type: 'generate', id: 3, params: {} });
    expect(sent[0]?.type).toBe('fatal');
    handle({ type: 'generate', id: 4, params: {} });
    expect(sent[1]).toEqual(sent[0]);
  });

  it('take_panic failing after a trap still yields a fatal message', () => {
    const { handle, sent } = run({
      generateThrows: new WebAssembly.RuntimeError('unreachable'),
      panic: new Error('instance is dead'),
    });
    handle({ type: 'generate', id: 1, params: {} });
    const fatal = sent[0];
    expect(fatal?.type === 'fatal' && fatal.message).toMatch(/trap \(unreachable\)/);
  });

  it('a stack overflow is fatal; a JS allocation failure is an error for that request only', () => {
    const overflow = run({ generateThrows: new RangeError('Maximum call stack size exceeded') });
    overflow.handle({ type: 'generate', id: 1, params: {} });
    expect(overflow.sent[0]?.type).toBe('fatal');

    const alloc = run({ positionsThrows: new RangeError('Array buffer allocation failed') });
    alloc.handle({ type: 'generate', id: 4, params: {} });
    expect(alloc.sent[0]).toEqual({
      type: 'error',
      id: 4,
      error: { kind: 'internal', message: 'Array buffer allocation failed' },
    });
  });

  it('typed core errors stay per-request and the worker keeps working', () => {
    const { handle, sent, state } = run({
      generateThrows: JSON.stringify({
        kind: 'budget',
        param: 'max_vertices',
        message: 'too big',
      }),
    });
    handle({ type: 'generate', id: 5, params: {} });
    handle({ type: 'generate', id: 6, params: {} });
    expect(sent.map((m) => m.type)).toEqual(['error', 'error']);
    expect(sent[0]).toEqual({
      type: 'error',
      id: 5,
      error: { kind: 'budget', param: 'max_vertices', message: 'too big' },
    });
    expect(state.generated).toBe(2);
  });

  it('isTrap classifies throws', () => {
    expect(isTrap(new WebAssembly.RuntimeError('unreachable'))).toBe(true);
    expect(isTrap(new WebAssembly.RuntimeError('divide by zero'))).toBe(true);
    expect(isTrap(new RangeError('Maximum call stack size exceeded'))).toBe(true);
    expect(isTrap(new RangeError('Invalid typed array length'))).toBe(false);
    expect(isTrap(new Error('unreachable'))).toBe(false);
    expect(isTrap('{"kind":"budget"}')).toBe(false);
  });

  it('debug-hang busy-waits for the given time on the injected clock, then answers idle', () => {
    const { wasm } = fakeWasm({});
    const sent: (WorkerResponse | DebugResponse)[] = [];
    let clock = 0;
    let reads = 0;
    const handle = createHandler(wasm, (message) => sent.push(message), {
      debug: debugHooks,
      now: () => {
        reads++;
        clock += 10;
        return clock;
      },
    });
    handle({ type: 'debug-hang', ms: 1_000 });
    expect(sent).toEqual([{ type: 'idle' }]);
    expect(clock).toBeGreaterThanOrEqual(1_010);
    expect(reads).toBeGreaterThan(90);
    handle({ type: 'generate', id: 1, params: {} });
    expect(sent[1]?.type).toBe('result');
  });

  it('refuses the debug messages unless the worker was started with the debug flag', () => {
    const { wasm } = fakeWasm({});
    let panics = 0;
    const core = Object.assign(wasm, { debug_panic: () => void panics++ });
    const sent: WorkerResponse[] = [];
    const handle = createHandler(core, (message) => sent.push(message));
    const debugHandle = handle as unknown as (request: DebugRequest) => void;
    expect(() => debugHandle({ type: 'debug-panic' })).toThrow(/debug flag/);
    expect(() => debugHandle({ type: 'debug-hang', ms: 5 })).toThrow(/debug flag/);
    expect(panics).toBe(0);
    expect(sent).toEqual([]);
    handle({ type: 'generate', id: 1, params: {} });
    expect(sent[0]?.type).toBe('result');
  });
});
