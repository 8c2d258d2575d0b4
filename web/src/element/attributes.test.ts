/** `<sylva-tree>` attributes → params. */
import { describe, expect, it } from 'vitest';
import { applyPreset, defaultParams } from 'sylva-trees/core';
import { realPresets, realRegistry } from 'sylva-trees/testing';
import { resolveTreeAttributes } from './attributes';

const registry = realRegistry();
const presets = realPresets();
const none = { preset: null, seed: null, params: null };

describe('resolveTreeAttributes', () => {
  it('no attributes: the defaults', () => {
    expect(resolveTreeAttributes(registry, presets, none)).toEqual({
      params: defaultParams(registry),
      volumes: [],
      edits: [],
      messages: [],
      fatal: null,
    });
  });

  it('preset, then params, then seed', () => {
    const aspen = presets.find((p) => p.name === 'quaking_aspen');
    expect(aspen).toBeDefined();
    const r = resolveTreeAttributes(registry, presets, {
      preset: 'quaking_aspen',
      seed: '7',
      params: 'v=1&levels=2&seed=3',
    });
    expect(r.fatal).toBeNull();
    expect(r.messages).toEqual([]);
    expect(r.params).toEqual({ ...applyPreset(registry, aspen!), levels: 2, seed: 7 });
  });

  it('reports bad values and unknown ids, keeping the rest', () => {
    const r = resolveTreeAttributes(registry, presets, {
      preset: null,
      seed: 'abc',
      params: 'levels=9&nope=1&scale=20&levels=2&%E0',
    });
    expect(r.fatal).toBeNull();
    expect(r.params.scale).toBe(20);
    expect(r.params.levels).toBe(defaultParams(registry).levels);
    expect(r.params.seed).toBe(defaultParams(registry).seed);
    expect(r.messages.join('\n')).toMatch(/levels.*out of range/);
    expect(r.messages.join('\n')).toMatch(/unknown parameter "nope"/);
    expect(r.messages.join('\n')).toMatch(/seed attribute/);
    expect(r.messages.length).toBeLessThanOrEqual(6);
  });

  it('unknown preset, wrong version or an over-long query are fatal', () => {
    expect(resolveTreeAttributes(registry, presets, { ...none, preset: 'baobab' }).fatal).toMatch(
      /Unknown preset "baobab"/,
    );
    expect(resolveTreeAttributes(registry, presets, { ...none, params: 'v=2' }).fatal).toMatch(
      /Unsupported/,
    );
    expect(
      resolveTreeAttributes(registry, presets, { ...none, params: 'a'.repeat(5000) }).fatal,
    ).toMatch(/too long/);
  });

  it('reads growth volumes from vol=', () => {
    const r = resolveTreeAttributes(registry, presets, {
      ...none,
      params: 'vol=1%3Bs%3Ac%3A0%2C5%2C0%2C2',
    });
    expect(r.volumes).toEqual([
      { kind: 'sphere', group: 'crown', centre: [0, 5, 0], size: [2, 2, 2] },
    ]);
  });

  it("reads hand edits from e= (a share link's edits), and says why it ignores bad ones", () => {
    const r = resolveTreeAttributes(registry, presets, {
      ...none,
      params: `levels=2&e=${encodeURIComponent('1~c80.410.-20')}`,
    });
    expect(r.edits).toEqual([{ op: 'cut', at: [0.8, 4.1, -0.2] }]);
    expect(r.params.levels).toBe(2);
    expect(r.messages).toEqual([]);
    const bad = resolveTreeAttributes(registry, presets, { ...none, params: 'e=1~x1.2' });
    expect(bad.edits).toEqual([]);
    expect(bad.messages.join(' ')).toMatch(/edit/i);
    expect(bad.fatal).toBeNull();
  });
});
