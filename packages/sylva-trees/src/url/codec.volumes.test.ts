/** Share-URL encoding of the growth volume primitives (`vol=`): round trips and malformed input. */
import fc from 'fast-check';
import { describe, expect, it } from 'vitest';
import type { VolumePrimitive } from '../core/types';
import { normalizeVolume } from '../core/volumes';
import { buildSearch, decodeVolumes, encodeVolumes, MAX_VOLUMES_LENGTH } from './codec';

const mm = (lo: number, hi: number) =>
  fc.integer({ min: Math.round(lo * 1000), max: Math.round(hi * 1000) }).map((n) => n / 1000);

const volume: fc.Arbitrary<VolumePrimitive> = fc
  .record({
    kind: fc.constantFrom('sphere' as const, 'box' as const, 'cylinder' as const),
    group: fc.constantFrom('crown' as const, 'shadow' as const, 'exclusion' as const),
    centre: fc.tuple(mm(-100, 100), mm(-100, 100), mm(-100, 100)),
    size: fc.tuple(mm(0.05, 100), mm(0.05, 100), mm(0.05, 100)),
  })
  .map(normalizeVolume);

describe('vol= codec', () => {
  it('round-trips any list of up to 32 primitives exactly', () => {
    fc.assert(
      fc.property(fc.array(volume, { maxLength: 32 }), (list) => {
        const text = encodeVolumes(list);
        expect(text.length).toBeLessThanOrEqual(MAX_VOLUMES_LENGTH);
        expect(decodeVolumes(text)).toEqual({ volumes: list, messages: [] });
      }),
      { numRuns: 200 },
    );
  });

  it('writes the compact versioned form and survives the page query', () => {
    const list: VolumePrimitive[] = [
      { kind: 'sphere', group: 'crown', centre: [0, 5, 0], size: [3, 3, 3] },
      { kind: 'box', group: 'exclusion', centre: [-2, 1.5, 0.25], size: [1, 3, 2] },
      { kind: 'cylinder', group: 'shadow', centre: [1, 4, -1], size: [0.5, 2, 0.5] },
    ];
    const text = encodeVolumes(list);
    expect(text).toBe('1;s:c:0,5,0,3;b:x:-2,1.5,0.25,1,3,2;c:s:1,4,-1,0.5,2');
    expect(encodeVolumes([])).toBe('');
    // `vol` is kept when the params part of the URL is rewritten.
    const search = buildSearch([], {}, `?v=1&vol=${encodeURIComponent(text)}`);
    expect(decodeVolumes(new URLSearchParams(search).get('vol')).volumes).toEqual(list);
  });

  it('rejects malformed values with messages, keeping the good primitives', () => {
    const bad = (value: string) => decodeVolumes(value);
    expect(bad('2;s:c:0,5,0,3')).toEqual({
      volumes: [],
      messages: [expect.stringContaining('unsupported version "2"')],
    });
    expect(bad('1;' + 's:c:0,5,0,3;'.repeat(200)).messages[0]).toContain('too long');
    const mixed = bad(
      '1;s:c:0,5,0,3;q:c:0,5,0,3;s:z:0,0,0,1;s:c:0,5,0;b:c:0,x,0,1,1,1;s:c:0,5,0,0;s:c:1e999,0,0,1',
    );
    expect(mixed.volumes).toEqual([
      { kind: 'sphere', group: 'crown', centre: [0, 5, 0], size: [3, 3, 3] },
    ]);
    expect(mixed.messages).toEqual([
      expect.stringContaining('vol[1] from the link: unknown kind "q"'),
      expect.stringContaining('unknown group "z"'),
      expect.stringContaining('takes 4 numbers, got 3'),
      expect.stringContaining('"x" is not a number'),
      expect.stringContaining('size is outside'),
      expect.stringContaining('not a finite number'),
    ]);
    expect(bad('1;s:c:Infinity,0,0,1').messages[0]).toContain('not a number');
    expect(bad('1;s:c:0x10,0,0,1').messages[0]).toContain('not a number');
    expect(bad('1;' + Array(33).fill('s:c:0,5,0,1').join(';')).volumes).toHaveLength(32);
    expect(bad('1;<script>:c:0,0,0,1').messages[0]).toContain('unknown kind "<script>"');
  });

  it('never throws on arbitrary text', () => {
    fc.assert(
      fc.property(fc.string({ maxLength: 200 }), (text) => {
        const { volumes } = decodeVolumes(`1;${text}`);
        expect(volumes.length).toBeLessThanOrEqual(32);
      }),
    );
  });
});
