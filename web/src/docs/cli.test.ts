/** The generated command-line reference the docs page renders. */
import { describe, expect, it } from 'vitest';
import { CLI_REFERENCE, codeSpans, synopsisParts } from './cli';

describe('CLI_REFERENCE', () => {
  it('has every command, each with a synopsis naming all its options and an example', () => {
    const names = CLI_REFERENCE.commands.map((c) => c.name);
    for (const name of [
      'generate',
      'params',
      'presets',
      'envelope',
      'bench',
      'leaf',
      'bench-leaf',
    ]) {
      expect(names).toContain(name);
    }
    for (const c of CLI_REFERENCE.commands) {
      expect(c.synopsis.startsWith(`sylva ${c.name}`)).toBe(true);
      expect(c.about.length, c.name).toBeGreaterThan(0);
      for (const o of c.options) expect(c.synopsis, c.name).toContain(o.flag);
      expect(c.examples.length, c.name).toBeGreaterThan(0);
      for (const e of c.examples)
        expect(e.startsWith(`sylva ${c.name} `) || e === `sylva ${c.name}`).toBe(true);
    }
  });

  it('documents the options the old copies missed', () => {
    const flags = (name: string) =>
      CLI_REFERENCE.commands.find((c) => c.name === name)?.options.map((o) => o.flag) ?? [];
    expect(flags('generate')).toEqual(
      expect.arrayContaining(['--volumes FILE.json', '--no-tangents', '--no-wind']),
    );
    expect(flags('leaf')).toEqual(expect.arrayContaining(['--svg FILE', '--step N']));
  });
});

describe('codeSpans', () => {
  it('splits help text into text and code', () => {
    expect(codeSpans('run `sylva help` or `-h`.')).toEqual([
      { text: 'run ', code: false },
      { text: 'sylva help', code: true },
      { text: ' or ', code: false },
      { text: '-h', code: true },
      { text: '.', code: false },
    ]);
    expect(codeSpans('no code')).toEqual([{ text: 'no code', code: false }]);
  });
});

describe('synopsisParts', () => {
  it('splits before every option, keeping each option whole', () => {
    expect(synopsisParts('sylva envelope --shape NAME [--samples N] [--set id=value]...')).toEqual([
      'sylva envelope',
      '--shape NAME',
      '[--samples N]',
      '[--set id=value]...',
    ]);
  });
});
