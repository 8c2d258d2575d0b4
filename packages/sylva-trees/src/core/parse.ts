/** Runtime validation of the JSON the wasm core returns (registry, presets, meta, errors). */
import type {
  Bounds,
  LeafInspection,
  MeshGroup,
  ParamId,
  ParamKind,
  ParamSpec,
  Preset,
  PresetId,
  SylvaError,
  SylvaErrorKind,
  Stage,
  TreeChanges,
  TreeMeta,
  EditReport,
} from './types';

type Json = Record<string, unknown>;

const PARAM_KINDS: readonly ParamKind[] = ['float', 'int', 'bool', 'enum'];
const STAGES: readonly Stage[] = ['skeleton', 'mesh', 'foliage', 'leaf', 'viewer'];
const ERROR_KINDS: readonly SylvaErrorKind[] = [
  'invalid_param',
  'unknown_param',
  'budget',
  'panic',
  'internal',
];

/** Thrown when core JSON does not match the contract. */
export class ContractError extends Error {
  override name = 'ContractError';
}

function isRecord(value: unknown): value is Json {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

function record(value: unknown, where: string): Json {
  if (!isRecord(value)) throw new ContractError(`${where}: expected an object`);
  return value;
}

function str(obj: Json, key: string, where: string): string {
  const v = obj[key];
  if (typeof v !== 'string') throw new ContractError(`${where}.${key}: expected a string`);
  return v;
}

function num(obj: Json, key: string, where: string): number {
  const v = obj[key];
  if (typeof v !== 'number' || !Number.isFinite(v)) {
    throw new ContractError(`${where}.${key}: expected a finite number`);
  }
  return v;
}

function array(value: unknown, where: string): unknown[] {
  if (!Array.isArray(value)) throw new ContractError(`${where}: expected an array`);
  return value as unknown[];
}

function numberRecord(value: unknown, where: string): Record<string, number> {
  const obj = record(value, where);
  const out: Record<string, number> = {};
  for (const key of Object.keys(obj)) out[key] = num(obj, key, where);
  return out;
}

function vec3(value: unknown, where: string): [number, number, number] {
  const a = array(value, where);
  if (a.length !== 3 || !a.every((x) => typeof x === 'number' && Number.isFinite(x))) {
    throw new ContractError(`${where}: expected [x, y, z]`);
  }
  return [a[0] as number, a[1] as number, a[2] as number];
}

function parseParamSpec(value: unknown, index: number): ParamSpec {
  const where = `registry[${index}]`;
  const o = record(value, where);
  const kind = str(o, 'kind', where);
  if (!PARAM_KINDS.includes(kind as ParamKind)) {
    throw new ContractError(`${where}.kind: unknown kind "${kind}"`);
  }
  const spec: ParamSpec = {
    // The core's ids are `ParamId`'s (the generated types are checked against the core).
    id: str(o, 'id', where) as ParamId,
    group: str(o, 'group', where),
    label: str(o, 'label', where),
    kind: kind as ParamKind,
    default: num(o, 'default', where),
    min: num(o, 'min', where),
    max: num(o, 'max', where),
    step: num(o, 'step', where),
    unit: typeof o.unit === 'string' ? o.unit : '',
    description: typeof o.description === 'string' ? o.description : '',
  };
  if (o.options !== undefined && o.options !== null) {
    spec.options = array(o.options, `${where}.options`).map((x) => String(x));
  }
  if (o.stage !== undefined) {
    const stage = str(o, 'stage', where);
    if (!STAGES.includes(stage as Stage)) {
      throw new ContractError(`${where}.stage: unknown stage "${stage}"`);
    }
    spec.stage = stage as Stage;
  }
  return spec;
}

/** Parses and validates `registry_json()` output. */
export function parseRegistry(text: string): ParamSpec[] {
  return array(JSON.parse(text), 'registry').map(parseParamSpec);
}

/**
 * Parses and validates `presets_json()` output (or, with `Name` = `LeafPresetId`,
 * `leaf_presets_json()`'s). Names and value ids are the core's, which the generated
 * `PresetId`, `LeafPresetId` and `ParamId` are checked against.
 */
export function parsePresets<Name extends string = PresetId>(text: string): Preset<Name>[] {
  return array(JSON.parse(text), 'presets').map((value, i) => {
    const where = `presets[${i}]`;
    const o = record(value, where);
    return {
      name: str(o, 'name', where) as Name,
      label: str(o, 'label', where),
      description: typeof o.description === 'string' ? o.description : '',
      values: numberRecord(o.values, `${where}.values`),
    };
  });
}

function parseGroup(value: unknown, i: number): MeshGroup {
  const where = `meta.groups[${i}]`;
  const o = record(value, where);
  const material = str(o, 'material', where);
  if (material !== 'bark' && material !== 'leaves') {
    throw new ContractError(`${where}.material: unknown material "${material}"`);
  }
  return { material, start: num(o, 'start', where), count: num(o, 'count', where) };
}

function parseChanges(value: unknown): TreeChanges {
  const o = record(value, 'meta.changes');
  const flag = (key: keyof TreeChanges): boolean => {
    if (typeof o[key] !== 'boolean')
      throw new ContractError(`meta.changes.${key}: expected a boolean`);
    return o[key];
  };
  return {
    skeleton: flag('skeleton'),
    bark: flag('bark'),
    placements: flag('placements'),
    leaf_mesh: flag('leaf_mesh'),
    leaf: flag('leaf'),
    ...(typeof o.shade === 'boolean' ? { shade: o.shade } : {}),
  };
}

/** Parses and validates a tree's `meta_json()` output. */
export function parseMeta(text: string): TreeMeta {
  const o = record(JSON.parse(text), 'meta');
  const b = record(o.bounds, 'meta.bounds');
  const bounds: Bounds = {
    min: vec3(b.min, 'meta.bounds.min'),
    max: vec3(b.max, 'meta.bounds.max'),
  };
  return {
    vertices: num(o, 'vertices', 'meta'),
    triangles: num(o, 'triangles', 'meta'),
    hash: typeof o.hash === 'string' ? o.hash : '',
    ...(typeof o.preview === 'boolean' ? { preview: o.preview } : {}),
    ...(o.changes !== undefined ? { changes: parseChanges(o.changes) } : {}),
    bounds,
    groups: array(o.groups, 'meta.groups').map(parseGroup),
    stage_ms: o.stage_ms === undefined ? {} : numberRecord(o.stage_ms, 'meta.stage_ms'),
    total_ms: num(o, 'total_ms', 'meta'),
    stems: typeof o.stems === 'number' ? o.stems : 0,
    leaves: typeof o.leaves === 'number' ? o.leaves : 0,
    leaf_hash: typeof o.leaf_hash === 'string' ? o.leaf_hash : '',
    leaf_texture: Array.isArray(o.leaf_texture)
      ? [Number(o.leaf_texture[0]), Number(o.leaf_texture[1])]
      : null,
    bark_type: typeof o.bark_type === 'number' ? o.bark_type : 0,
    ...(Array.isArray(o.edits) ? { edits: o.edits.map(parseEditReport) } : {}),
  };
}

/** One entry of the meta's `edits`: the op, whether it resolved and why not. */
function parseEditReport(value: unknown, i: number): EditReport {
  const o = record(value, `meta.edits[${i}]`);
  return {
    op: typeof o.op === 'string' ? o.op : '',
    resolved: o.resolved !== false,
    ...(typeof o.why === 'string' ? { why: o.why } : {}),
  };
}

/** Parses and validates `leaf_inspect()` output. */
export function parseLeafInspection(text: string): LeafInspection {
  const o = record(JSON.parse(text), 'leaf');
  return {
    svg: str(o, 'svg', 'leaf'),
    iterations: num(o, 'iterations', 'leaf'),
    nodes: num(o, 'nodes', 'leaf'),
    links: num(o, 'links', 'leaf'),
    segments: num(o, 'segments', 'leaf'),
    auxins: num(o, 'auxins', 'leaf'),
    triangles: num(o, 'triangles', 'leaf'),
    hash: str(o, 'hash', 'leaf'),
  };
}

/** Turns whatever `generate` threw (JSON string, Error, other) into a SylvaError. */
export function toSylvaError(thrown: unknown): SylvaError {
  if (typeof thrown === 'string') {
    try {
      const o: unknown = JSON.parse(thrown);
      if (isRecord(o) && typeof o.message === 'string') {
        const kind = ERROR_KINDS.includes(o.kind as SylvaErrorKind)
          ? (o.kind as SylvaErrorKind)
          : 'internal';
        const err: SylvaError = { kind, message: o.message };
        if (typeof o.param === 'string') err.param = o.param;
        return err;
      }
    } catch {
      // not JSON: fall through and use the raw text
    }
    return { kind: 'internal', message: thrown };
  }
  if (thrown instanceof Error) return { kind: 'internal', message: thrown.message };
  return { kind: 'internal', message: String(thrown) };
}
