/**
 * The generated TypeScript module (`generated/params.ts`, written by `npm run docs` from the
 * native CLI) holds exactly what the wasm core the package ships reports: the same registry, in
 * the same order, the same preset names and values. (`cargo test -p sylva-cli` fails when the
 * file differs from what the CLI prints.)
 */
import { describe, expect, it } from 'vitest';
import {
  LEAF_PRESET_IDS,
  PARAM_SPECS,
  PRESET_IDS,
  PRESET_VALUES,
  type ParamOptions,
} from './generated/params';
import { parsePresets } from './parse';
import { loadWasm, realPresets, realRegistry } from '../testing/realWasm';

describe('generated/params.ts', () => {
  it('is the wasm core registry, entry by entry, in registry order', () => {
    const registry = realRegistry();
    expect(Object.keys(PARAM_SPECS)).toEqual(registry.map((s) => s.id));
    for (const spec of registry) {
      const generated = { id: spec.id, ...PARAM_SPECS[spec.id], description: spec.description };
      expect(generated).toEqual(spec);
    }
  });

  it('has every preset of the wasm core with its values', () => {
    const presets = realPresets();
    expect([...PRESET_IDS]).toEqual(presets.map((p) => p.name));
    for (const preset of presets) expect(PRESET_VALUES[preset.name]).toEqual(preset.values);
    const leaf = parsePresets(loadWasm().leaf_presets_json?.() ?? '[]');
    expect([...LEAF_PRESET_IDS]).toEqual(leaf.map((p) => p.name));
  });

  it('types enum values by their option labels', () => {
    const shape: ParamOptions['shape'] = 'Tend Flame';
    expect(PARAM_SPECS.shape.options.indexOf(shape)).toBe(PRESET_VALUES.quaking_aspen.shape);
  });
});
