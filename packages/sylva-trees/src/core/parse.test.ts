/**
 * The runtime checks of the core's JSON accept what the real wasm core sends, field for field
 * (the generated `TreeMeta`), and reject a corrupted message.
 */
import { describe, expect, it } from 'vitest';
import { ContractError, parseMeta, toSylvaError } from './parse';
import { loadWasm } from '../testing/realWasm';
import { CORE_ERROR_KINDS } from './generated/payloads';

const PARAMS = JSON.stringify({ levels: 2 });

describe('parseMeta', () => {
  it("keeps every field of a generated tree's meta", () => {
    const tree = loadWasm().generate(PARAMS);
    const text = tree.meta_json();
    tree.free();
    const meta = parseMeta(text);
    expect(meta).toEqual(JSON.parse(text));
    expect(meta.hash).toMatch(/^[0-9a-f]{16}$/);
    expect(meta.envelope.length).toBeGreaterThan(0);
  });

  it("keeps every field of a session update's meta, with an empty hash", () => {
    const session = new (loadWasm().Session)();
    try {
      const text = session.update(PARAMS, -1);
      const meta = parseMeta(text);
      expect(meta).toEqual({ ...JSON.parse(text), hash: '' });
      expect(meta.from).toBe('skeleton');
      expect(meta.changes?.bark).toBe(true);
      expect(meta.preview).toBe(false);
    } finally {
      session.free();
    }
  });

  it('rejects a corrupted meta', () => {
    const tree = loadWasm().generate(PARAMS);
    const good = JSON.parse(tree.meta_json()) as Record<string, unknown>;
    tree.free();
    const corrupt = (patch: Record<string, unknown>): (() => unknown) => {
      return () => parseMeta(JSON.stringify({ ...good, ...patch }));
    };
    expect(corrupt({ leaf_hash: undefined })).toThrow(ContractError);
    expect(corrupt({ groups: [{ material: 'wood', start: 0, count: 3 }] })).toThrow(
      'meta.groups[0].material: unknown value "wood"',
    );
    expect(corrupt({ envelope: [[1]] })).toThrow('meta.envelope[0]: expected [a, b]');
    expect(corrupt({ from: 'roots' })).toThrow('meta.from: unknown value "roots"');
    expect(corrupt({ changes: { bark: true } })).toThrow(ContractError);
  });
});

describe('toSylvaError', () => {
  it("keeps every kind of the core's errors", () => {
    expect(CORE_ERROR_KINDS).toContain('input');
    let thrown: unknown;
    try {
      loadWasm().generate('[1]');
    } catch (e) {
      thrown = e;
    }
    expect(toSylvaError(thrown)).toMatchObject({ kind: 'input' });
    expect(toSylvaError('{"kind": "bogus", "message": "m"}').kind).toBe('internal');
  });
});
