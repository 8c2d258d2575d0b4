/**
 * `<sylva-tree>` attributes → generator params (pure): the `preset` (or the defaults), then the
 * `params` query (`id=value&...`, with `vol=` growth volumes and `e=` hand edits, validated
 * exactly like a share link), then `seed`.
 */
import {
  applyPreset,
  defaultParams,
  type Params,
  type ParamSpec,
  type Edit,
  type Preset,
  type VolumePrimitive,
} from 'sylva-trees/core';
import {
  decodeEdits,
  decodeVolumes,
  EDITS_KEY,
  FORMAT_VERSION,
  MAX_QUERY_LENGTH,
  parseValue,
  shown,
  VOLUMES_KEY,
} from 'sylva-trees/url';

/** The attributes that choose the tree. */
export interface TreeAttributes {
  preset: string | null;
  seed: string | null;
  params: string | null;
}

/** What the element generates, plus problems to show (a fatal one means: nothing generated). */
export interface ResolvedTree {
  params: Params;
  volumes: VolumePrimitive[];
  /** The hand edits (`e=` in `params`, as a share link has them). */
  edits: Edit[];
  /** Ignored values: the tree is still generated without them. */
  messages: string[];
  /** A problem that makes the request meaningless (unknown preset, over-long params). */
  fatal: string | null;
}

/** Most problems listed for one element. */
const MAX_LISTED = 6;

function decodePiece(text: string): string | null {
  try {
    return decodeURIComponent(text.replace(/\+/g, ' '));
  } catch {
    return null;
  }
}

/** Resolves the attributes against the registry and presets. Never throws. */
export function resolveTreeAttributes(
  registry: readonly ParamSpec[],
  presets: readonly Preset[],
  attributes: TreeAttributes,
): ResolvedTree {
  const messages: string[] = [];
  const note = (line: string): void => {
    if (messages.length < MAX_LISTED) messages.push(line);
  };
  const fail = (fatal: string): ResolvedTree => ({
    params: defaultParams(registry),
    volumes: [],
    edits: [],
    messages,
    fatal,
  });

  let params: Params;
  const presetName = attributes.preset?.trim() ?? '';
  if (presetName !== '') {
    const preset = presets.find((p) => p.name === presetName || p.label === presetName);
    if (!preset) {
      const names = presets.map((p) => p.name).join(', ');
      return fail(`Unknown preset "${shown(presetName)}" (known: ${names}).`);
    }
    params = applyPreset(registry, preset);
  } else {
    params = defaultParams(registry);
  }

  let volumes: VolumePrimitive[] = [];
  let edits: Edit[] = [];
  const query = (attributes.params ?? '').trim().replace(/^\?/, '');
  if (query.length > MAX_QUERY_LENGTH) {
    return fail(`The params attribute is too long (limit ${MAX_QUERY_LENGTH} characters).`);
  }
  const byId = new Map<string, ParamSpec>(registry.map((s) => [s.id, s]));
  const seen = new Set<string>();
  for (const piece of query.split('&')) {
    if (piece.trim() === '') continue;
    const eq = piece.indexOf('=');
    const key = decodePiece((eq < 0 ? piece : piece.slice(0, eq)).trim());
    const raw = decodePiece((eq < 0 ? '' : piece.slice(eq + 1)).trim());
    if (key === null || raw === null) {
      note(`Ignored "${shown(piece)}" in params: bad %-encoding.`);
      continue;
    }
    if (key === 'v') {
      if (raw !== FORMAT_VERSION) {
        return fail(`Unsupported params version "${shown(raw)}" (this Sylva reads v=1).`);
      }
      continue;
    }
    if (key === VOLUMES_KEY) {
      const decoded = decodeVolumes(raw);
      volumes = decoded.volumes;
      decoded.messages.forEach(note);
      continue;
    }
    if (key === EDITS_KEY) {
      const decoded = decodeEdits(raw);
      edits = decoded.edits;
      decoded.messages.forEach(note);
      continue;
    }
    const spec = byId.get(key);
    if (!spec) {
      note(`Ignored unknown parameter "${shown(key)}" in params.`);
      continue;
    }
    if (seen.has(key)) {
      note(`Ignored a repeated "${key}" in params; kept its first value.`);
      continue;
    }
    seen.add(key);
    const value = parseValue(spec, raw);
    if (typeof value === 'number') params[spec.id] = value;
    else note(`Ignored "${key}" in params: ${value}.`);
  }

  const seedText = attributes.seed?.trim() ?? '';
  const seedSpec = byId.get('seed');
  if (seedText !== '' && seedSpec) {
    const value = parseValue(seedSpec, seedText);
    if (typeof value === 'number') params.seed = value;
    else note(`Ignored the seed attribute: ${value}.`);
  }
  return { params, volumes, edits, messages, fatal: null };
}
