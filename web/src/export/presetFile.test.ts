/** Preset JSON files: save → load round trip, and clear errors for bad files. */
import { describe, expect, it } from 'vitest';
import { applyPreset, defaultParams } from 'sylva-trees/core';
import { realPresets, realRegistry } from 'sylva-trees/testing';
import { parsePresetFile, presetFileName, presetFileText } from './presetFile';

const registry = realRegistry();
const presets = realPresets();

describe('preset files', () => {
  it('hold every registry value and round-trip every preset exactly', () => {
    for (const preset of presets) {
      const params = { ...applyPreset(registry, preset), seed: 12345 };
      const text = presetFileText(registry, params);
      const data = JSON.parse(text) as { sylva: number; params: Record<string, number> };
      expect(data.sylva).toBe(1);
      expect(Object.keys(data.params)).toEqual(registry.map((s) => s.id));
      const back = parsePresetFile(registry, text);
      expect(back).toEqual({ ok: true, params, messages: [] });
    }
  });

  it('a partial file fills in defaults; unknown ids are a notice; booleans are accepted', () => {
    const r = parsePresetFile(
      registry,
      JSON.stringify({ sylva: 1, params: { levels: 2, future_param: 3, show_preview: true } }),
    );
    expect(r.ok).toBe(true);
    if (!r.ok) return;
    expect(r.params).toEqual({ ...defaultParams(registry), levels: 2, show_preview: 1 });
    expect(r.messages).toEqual(['Ignored 1 unknown parameter in the preset file: future_param.']);
  });

  it('rejects files that are not Sylva presets, naming the problem', () => {
    const bad = (text: string) => {
      const r = parsePresetFile(registry, text);
      expect(r.ok).toBe(false);
      return r.ok ? '' : r.error;
    };
    expect(bad('not json')).toMatch(/not JSON/);
    expect(bad('[1,2]')).toMatch(/not a Sylva preset/);
    expect(bad('{"params":{}}')).toMatch(/not a Sylva preset/);
    expect(bad('{"sylva":2,"params":{}}')).toMatch(/Unsupported preset file version 2/);
    expect(bad('{"sylva":1}')).toMatch(/no "params"/);
    expect(bad('{"sylva":1,"params":{"levels":99}}')).toMatch(
      /Levels \(levels\): "99" is out of range/,
    );
    expect(bad('{"sylva":1,"params":{"levels":"3"}}')).toMatch(/levels.*not a number/);
    expect(bad('{"sylva":1,"params":{"levels":2.5}}')).toMatch(/not an integer/);
    expect(bad('{"sylva":1,"params":{"seed":null}}')).toMatch(/seed.*not a number/);
    expect(bad(' '.repeat(300 * 1024))).toMatch(/too large/);
  });

  it('names the file after the preset and seed', () => {
    expect(presetFileName({ seed: 7 }, 'quaking_aspen')).toBe('sylva-quaking_aspen-seed7.json');
    expect(presetFileName({}, null)).toBe('sylva-tree.json');
    expect(presetFileName({ seed: 1 }, '../x y')).toBe('sylva--x-y-seed1.json');
  });
});
