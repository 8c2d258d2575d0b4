/**
 * Preset files: `{"sylva":1,"params":{id: value, ...}}` with every registry value. Loading checks
 * each value with the share-link validation (`parseValue`), so a file can hold nothing a link
 * could not; any bad value rejects the whole file (the current tree stays).
 */
import { defaultParams, normalizeValue, type Params, type ParamSpec } from 'sylva-trees/core';
import { formatNumber, parseValue, shown } from 'sylva-trees/url';

/** Format version written as `"sylva"`. */
export const PRESET_FILE_VERSION = 1;
/** Largest preset file read (bytes). */
export const MAX_PRESET_FILE_BYTES = 256 * 1024;
const MAX_LISTED = 6;

/** The preset file text for `params` (every registry value, in registry order). */
export function presetFileText(registry: readonly ParamSpec[], params: Params): string {
  const values: Params = {};
  for (const spec of registry) {
    values[spec.id] = normalizeValue(spec, params[spec.id] ?? spec.default);
  }
  return `${JSON.stringify({ sylva: PRESET_FILE_VERSION, params: values }, null, 2)}\n`;
}

/** A file name for the preset: `sylva-<preset or tree>-seed<N>.json`. */
export function presetFileName(params: Params, presetName: string | null): string {
  const base = (presetName ?? 'tree').replace(/[^a-z0-9_-]+/gi, '-').toLowerCase() || 'tree';
  const seed = params.seed;
  return `sylva-${base}${seed === undefined ? '' : `-seed${seed}`}.json`;
}

/** Result of reading a preset file: params (defaults for missing ids) or an error. */
export type PresetFileResult =
  { ok: true; params: Params; messages: string[] } | { ok: false; error: string };

function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/**
 * Reads a preset file. Unknown ids are skipped with a notice (files from newer versions still
 * load); missing ids take their default; a value that a share link would reject fails the load.
 */
export function parsePresetFile(registry: readonly ParamSpec[], text: string): PresetFileResult {
  if (text.length > MAX_PRESET_FILE_BYTES) {
    return { ok: false, error: `The file is too large for a Sylva preset (${text.length} bytes).` };
  }
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch {
    return { ok: false, error: 'The file is not JSON: expected {"sylva":1,"params":{...}}.' };
  }
  if (!isRecord(data) || !('sylva' in data)) {
    return {
      ok: false,
      error: 'The file is not a Sylva preset: expected {"sylva":1,"params":{...}}.',
    };
  }
  if (data.sylva !== PRESET_FILE_VERSION) {
    const version = shown(JSON.stringify(data.sylva) ?? String(data.sylva));
    return {
      ok: false,
      error: `Unsupported preset file version ${version} (this Sylva reads "sylva": ${PRESET_FILE_VERSION}).`,
    };
  }
  if (!isRecord(data.params)) {
    return { ok: false, error: 'The preset file has no "params" object.' };
  }
  const byId = new Map<string, ParamSpec>(registry.map((s) => [s.id, s]));
  const params = defaultParams(registry);
  const problems: string[] = [];
  const unknown: string[] = [];
  for (const [id, value] of Object.entries(data.params)) {
    const spec = byId.get(id);
    if (!spec) {
      unknown.push(shown(id));
      continue;
    }
    const raw =
      typeof value === 'number'
        ? formatNumber(value)
        : typeof value === 'boolean' && spec.kind === 'bool'
          ? value
            ? '1'
            : '0'
          : null;
    const parsed = raw === null ? `${shown(JSON.stringify(value) ?? '')} is not a number` : null;
    const result = parsed ?? parseValue(spec, raw ?? '');
    if (typeof result === 'number') params[spec.id] = result;
    else problems.push(`${spec.label} (${id}): ${result}`);
  }
  if (problems.length > 0) {
    const listed = problems.slice(0, MAX_LISTED).join('; ');
    const more = problems.length > MAX_LISTED ? `; and ${problems.length - MAX_LISTED} more` : '';
    return { ok: false, error: `The preset file has invalid values: ${listed}${more}.` };
  }
  const messages =
    unknown.length > 0
      ? [
          `Ignored ${unknown.length} unknown parameter${unknown.length === 1 ? '' : 's'} in the preset file: ${unknown.slice(0, MAX_LISTED).join(', ')}${unknown.length > MAX_LISTED ? ', …' : ''}.`,
        ]
      : [];
  return { ok: true, params, messages };
}
