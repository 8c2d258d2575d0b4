/**
 * Runtime validation of the JSON the wasm core returns (registry, presets, meta, errors): it
 * guards against a corrupted worker message. The shapes are the generated payload interfaces
 * (`generated/payloads.ts`), which a Rust test keeps equal to what the core sends.
 */
import { CORE_ERROR_KINDS, MATERIALS, STAGES } from './generated/payloads';
import type {
  Bounds,
  EditReport,
  LeafInspection,
  MaterialName,
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
} from './types';

type Json = Record<string, unknown>;

const PARAM_KINDS: readonly ParamKind[] = ['float', 'int', 'bool', 'enum'];
const ERROR_KINDS: readonly SylvaErrorKind[] = [...CORE_ERROR_KINDS, 'panic', 'internal'];

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
  if (o.stage !== undefined) spec.stage = oneOf<Stage>(o, 'stage', where, STAGES);
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

function bool(obj: Json, key: string, where: string): boolean {
  const v = obj[key];
  if (typeof v !== 'boolean') throw new ContractError(`${where}.${key}: expected a boolean`);
  return v;
}

function pair(value: unknown, where: string): [number, number] {
  const a = array(value, where);
  if (a.length !== 2 || !a.every((x) => typeof x === 'number' && Number.isFinite(x))) {
    throw new ContractError(`${where}: expected [a, b]`);
  }
  return [a[0] as number, a[1] as number];
}

function oneOf<T extends string>(obj: Json, key: string, where: string, values: readonly T[]): T {
  const v = str(obj, key, where);
  if (!values.includes(v as T)) throw new ContractError(`${where}.${key}: unknown value "${v}"`);
  return v as T;
}

function parseGroup(value: unknown, i: number): MeshGroup {
  const where = `meta.groups[${i}]`;
  const o = record(value, where);
  const material: MaterialName = oneOf(o, 'material', where, MATERIALS);
  return { material, start: num(o, 'start', where), count: num(o, 'count', where) };
}

function parseChanges(value: unknown): TreeChanges {
  const where = 'meta.changes';
  const o = record(value, where);
  return {
    skeleton: bool(o, 'skeleton', where),
    bark: bool(o, 'bark', where),
    placements: bool(o, 'placements', where),
    leaf_mesh: bool(o, 'leaf_mesh', where),
    leaf: bool(o, 'leaf', where),
    shade: bool(o, 'shade', where),
  };
}

/** A tree's `meta_json()` or a session's `update()`: the generated `TreeMeta`, all checked. */
export function parseMeta(text: string): TreeMeta {
  const o = record(JSON.parse(text), 'meta');
  const b = record(o.bounds, 'meta.bounds');
  const bounds: Bounds = {
    min: vec3(b.min, 'meta.bounds.min'),
    max: vec3(b.max, 'meta.bounds.max'),
  };
  const at = 'meta';
  return {
    vertices: num(o, 'vertices', at),
    triangles: num(o, 'triangles', at),
    stems: num(o, 'stems', at),
    holes: num(o, 'holes', at),
    bounds,
    groups: array(o.groups, 'meta.groups').map(parseGroup),
    envelope: array(o.envelope, 'meta.envelope').map((p, i) => pair(p, `meta.envelope[${i}]`)),
    leaves: num(o, 'leaves', at),
    leaf_hash: str(o, 'leaf_hash', at),
    leaf_texture: o.leaf_texture === null ? null : pair(o.leaf_texture, 'meta.leaf_texture'),
    bark_type: num(o, 'bark_type', at),
    stage_ms: numberRecord(o.stage_ms, 'meta.stage_ms'),
    total_ms: num(o, 'total_ms', at),
    hash: o.hash === undefined ? '' : str(o, 'hash', at),
    ...(o.preview !== undefined ? { preview: bool(o, 'preview', at) } : {}),
    ...(o.from !== undefined ? { from: oneOf<Stage>(o, 'from', at, STAGES) } : {}),
    ...(o.changes !== undefined ? { changes: parseChanges(o.changes) } : {}),
    ...(o.edits !== undefined ? { edits: array(o.edits, 'meta.edits').map(parseEditReport) } : {}),
  };
}

function parseEditReport(value: unknown, i: number): EditReport {
  const where = `meta.edits[${i}]`;
  const o = record(value, where);
  return {
    op: str(o, 'op', where),
    resolved: bool(o, 'resolved', where),
    ...(o.why !== undefined ? { why: str(o, 'why', where) } : {}),
    ...(o.pending_year !== undefined ? { pending_year: num(o, 'pending_year', where) } : {}),
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
