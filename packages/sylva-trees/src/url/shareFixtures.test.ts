/**
 * The share links the core's codec (core-rs/sylva-core/src/share, used by the Python package and
 * the Blender add-on) is tested against (core-rs/sylva-core/tests/share_links.json): the
 * studio's codec writes exactly these links for these trees and reads them back to the same
 * values, primitives and edits, so a link copied in either one opens the same tree in the other.
 */
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { applyPreset, defaultParams } from '../core/params';
import { parseEditsValue } from '../core/editsJson';
import type { Params, VolumePrimitive } from '../core/types';
import { realPresets, realRegistry } from '../testing/realWasm';
import { buildSearch, decodeQuery, decodeVolumes, encodeVolumes } from './codec';
import { decodeEdits, encodeEdits } from './editsCodec';

interface Fixture {
  name: string;
  preset?: string;
  values: Record<string, number>;
  volumes?: CoreVolume[];
  edits?: unknown[];
  link: string;
}
interface CoreVolume {
  kind: VolumePrimitive['kind'];
  group: VolumePrimitive['group'];
  centre: [number, number, number];
  radius?: number;
  height?: number;
  size?: [number, number, number];
}

const file = new URL('../../../../core-rs/sylva-core/tests/share_links.json', import.meta.url);
const fixtures = (JSON.parse(readFileSync(file, 'utf8')) as { links: Fixture[] }).links;
const registry = realRegistry();
const presets = realPresets();

/** The studio's form of a primitive in the core's JSON form. */
function volume(v: CoreVolume): VolumePrimitive {
  const r = v.radius ?? 0;
  const size: [number, number, number] =
    v.kind === 'sphere' ? [r, r, r] : v.kind === 'cylinder' ? [r, v.height ?? 0, r] : v.size!;
  return { kind: v.kind, group: v.group, centre: v.centre, size };
}

/** The fixture's parameters as the studio holds them: a preset (or the defaults) and values. */
function paramsOf(f: Fixture): Params {
  const preset = presets.find((p) => p.name === f.preset);
  const params = preset ? applyPreset(registry, preset) : defaultParams(registry);
  return { ...params, ...f.values };
}

describe('share links shared with the core', () => {
  it.each(fixtures)('$name: the studio writes the link', (f) => {
    const kept = new URLSearchParams();
    const volumes = encodeVolumes((f.volumes ?? []).map(volume));
    if (volumes) kept.set('vol', volumes);
    const edits = encodeEdits(parseEditsValue(f.edits ?? []));
    if (edits) kept.set('e', edits);
    expect(buildSearch(registry, paramsOf(f), kept.toString())).toBe(`?${f.link}`);
  });

  it.each(fixtures)('$name: the studio reads the link back', (f) => {
    const query = new URLSearchParams(f.link);
    const decoded = decodeQuery(registry, f.link);
    expect(decoded.messages).toEqual([]);
    expect(decoded.params).toEqual(paramsOf(f));
    expect(decodeVolumes(query.get('vol')).volumes).toEqual((f.volumes ?? []).map(volume));
    expect(decodeEdits(query.get('e')).edits).toEqual(parseEditsValue(f.edits ?? []));
  });
});
