/** Worker-side request handling over an initialised wasm API (no Worker globals; testable in Node). */
import {
  parseLeafInspection,
  parseMeta,
  parsePresets,
  parseRegistry,
  toSylvaError,
} from '../core/parse';
import type {
  BarkTextureBuffers,
  FoliageBuffers,
  TreeMeta,
  WasmApi,
  WasmTree,
} from '../core/types';
import { volumeToCore } from '../core/volumes';
import { lodsResponse } from '../lod/lodHandler';
import { exportFormatsOf, exportTree } from '../export/exportHandler';
import type { LeafRequest, ReadyResponse, WorkerRequest, WorkerResponse } from './protocol';

/** Sends a response, transferring the given buffers. */
export type Post = (message: WorkerResponse, transfer: Transferable[]) => void;

/** Builds the `ready` message from the wasm registry, presets and version. */
export function readyMessage(wasm: WasmApi): ReadyResponse {
  return {
    type: 'ready',
    registry: parseRegistry(wasm.registry_json()),
    presets: parsePresets(wasm.presets_json()),
    version: wasm.core_version(),
    leafPresets: wasm.leaf_presets_json ? parsePresets(wasm.leaf_presets_json()) : [],
    exportFormats: exportFormatsOf(wasm),
  };
}

/**
 * Message of a wasm trap: the core's recorded panic text, else the trap itself (a failed
 * allocation aborts without a panic message, as `unreachable`; a memory fault reads
 * `memory access out of bounds`).
 */
function panicMessage(wasm: WasmApi, thrown: unknown): string {
  let recorded: string | undefined;
  try {
    recorded = wasm.take_panic();
  } catch {
    recorded = undefined;
  }
  if (recorded) return recorded;
  const text = thrown instanceof Error ? thrown.message : String(thrown);
  return `WebAssembly trap (${text || 'no message'}): the generator aborted, possibly out of memory`;
}

/**
 * Whether a throw means the wasm instance is no longer usable: any trap (`unreachable` from a
 * panic or a failed allocation, `memory access out of bounds`, ...), or a stack overflow, which
 * leaves Rust's shadow stack mid-frame.
 */
export function isTrap(thrown: unknown): boolean {
  if (thrown instanceof WebAssembly.RuntimeError) return true;
  return thrown instanceof RangeError && /call stack/i.test(thrown.message);
}

/** Blocks the worker thread for `ms` (debug hook: lets tests hit the scheduler's time limit). */
function busyWait(ms: number, now: () => number): void {
  const end = now() + ms;
  while (now() < end) {
    // spin
  }
}

/** The leaves of a generated tree; the texture only when the leaf shape differs from `sentHash`. */
export function foliageOf(tree: WasmTree, meta: TreeMeta, sentHash: string): FoliageBuffers {
  const leafHash = meta.leaf_hash ?? '';
  const size = meta.leaf_texture;
  const none = new Float32Array(0);
  // Read (copied out of the module) only when it is sent.
  const rgba = size && leafHash !== sentHash ? tree.leaf_texture?.() : undefined;
  const texture = size && rgba?.length ? { width: size[0], height: size[1], rgba } : null;
  return {
    positions: tree.leaf_positions?.() ?? none.slice(),
    normals: tree.leaf_normals?.() ?? none.slice(),
    uvs: tree.leaf_uvs?.() ?? none.slice(),
    indices: tree.leaf_indices?.() ?? new Uint32Array(0),
    matrices: tree.leaf_matrices?.() ?? none.slice(),
    colors: tree.leaf_colors?.() ?? none.slice(),
    texture,
    // A bare tree sent no texture: the next leafy tree must send one.
    leafHash: size ? leafHash : '',
  };
}

/** Edge length of the baked bark textures (texels). */
export const BARK_TEXTURE_SIZE = 256;

/** The core's maps of bark type `kind`, or undefined when this wasm build has none. */
export function barkOf(wasm: WasmApi, kind = 0): BarkTextureBuffers | undefined {
  if (typeof wasm.bark_maps !== 'function' || typeof wasm.bark_style_json !== 'function') {
    return undefined;
  }
  const maps = wasm.bark_maps(kind, BARK_TEXTURE_SIZE);
  const size = Math.round(Math.sqrt(maps.length / 12));
  if (size < 1 || size * size * 12 !== maps.length) return undefined;
  const n = size * size * 4;
  // Three copies, so that each map's buffer can be transferred on its own.
  const [color, normal, orm] = [0, 1, 2].map((k) => maps.slice(k * n, (k + 1) * n)) as [
    Uint8Array,
    Uint8Array,
    Uint8Array,
  ];
  const style = JSON.parse(wasm.bark_style_json(kind)) as BarkTextureBuffers['style'];
  return { size, kind, color, normal, orm, style };
}

/** The bark occlusion (one byte per vertex), empty when the core has none or it does not fit. */
export function shadeOf(tree: WasmTree, vertices: number): Uint8Array {
  const shade = tree.shade?.();
  return shade instanceof Uint8Array && shade.length === vertices ? shade : new Uint8Array(0);
}

/**
 * The tree's wind data (8 floats per vertex), read defensively: empty when the core has no
 * `wind()` getter yet or its length does not match the vertex count.
 */
export function windOf(tree: WasmTree, vertices: number): Float32Array {
  const read = (tree as { wind?: () => Float32Array }).wind;
  if (typeof read !== 'function') return new Float32Array(0);
  const wind = read.call(tree);
  return wind instanceof Float32Array && wind.length === vertices * 8 && vertices > 0
    ? wind
    : new Float32Array(0);
}

function foliageTransfer(f: FoliageBuffers): Transferable[] {
  const buffers: Transferable[] = [
    f.positions.buffer,
    f.normals.buffer,
    f.uvs.buffer,
    f.indices.buffer,
    f.matrices.buffer,
    f.colors.buffer,
  ];
  if (f.texture) buffers.push(f.texture.rgba.buffer);
  return buffers;
}

/** Answers a leaf inspector request (an invalid parameter is a typed error, a trap is fatal). */
function handleLeaf(
  wasm: WasmApi,
  request: LeafRequest,
  post: Post,
  die: (t: unknown) => void,
): void {
  try {
    if (!wasm.leaf_inspect) throw new Error('this generator has no leaf inspector');
    const text = wasm.leaf_inspect(
      JSON.stringify(request.params),
      request.step,
      request.triangulation,
    );
    post({ type: 'leaf', id: request.id, ...parseLeafInspection(text) }, []);
  } catch (thrown) {
    if (isTrap(thrown)) die(thrown);
    else post({ type: 'error', id: request.id, error: toSylvaError(thrown) }, []);
  }
}

/** Creates the request handler; after a panic it answers every request with `fatal`. */
export function createHandler(
  wasm: WasmApi,
  post: Post,
  now: () => number = () => performance.now(),
): (request: WorkerRequest) => void {
  let deadMessage: string | null = null;
  // The leaf texture is sent once per leaf shape: the hash of the last one sent.
  let sentLeafHash = '';
  // The bark textures go out with the first result and again when the bark type changes.
  let barkSent: number | null = null;

  const die = (thrown: unknown): void => {
    deadMessage = panicMessage(wasm, thrown);
    post({ type: 'fatal', message: deadMessage }, []);
  };

  return (request) => {
    if (deadMessage !== null) {
      post({ type: 'fatal', message: deadMessage }, []);
      return;
    }
    if (request.type === 'debug-hang') {
      busyWait(request.ms, now);
      post({ type: 'idle' }, []);
      return;
    }
    if (request.type === 'debug-panic') {
      try {
        wasm.debug_panic();
        post({ type: 'fatal', message: 'debug_panic() returned without panicking' }, []);
      } catch (thrown) {
        die(thrown);
      }
      return;
    }
    if (request.type === 'leaf') {
      handleLeaf(wasm, request, post, die);
      return;
    }
    if (request.type === 'export') {
      try {
        exportTree(wasm, request, post);
      } catch (thrown) {
        if (isTrap(thrown)) die(thrown);
        else post({ type: 'error', id: request.id, error: toSylvaError(thrown) }, []);
      }
      return;
    }
    if (request.type === 'lods') {
      try {
        post(...lodsResponse(wasm, request));
      } catch (thrown) {
        if (isTrap(thrown)) die(thrown);
        else post({ type: 'error', id: request.id, error: toSylvaError(thrown) }, []);
      }
      return;
    }
    let tree: WasmTree;
    try {
      const input = request.volumes?.length
        ? { ...request.params, volumes: request.volumes.map(volumeToCore) }
        : request.params;
      const json = JSON.stringify(input);
      const id = request.id;
      let lastStep = -1;
      // Progress while growing: at most 50 messages per request (every 2 %).
      const progress = (fraction: number): void => {
        const step = Math.floor(fraction * 50);
        if (step === lastStep) return;
        lastStep = step;
        post({ type: 'progress', id, fraction }, []);
      };
      tree = wasm.generate_with_progress
        ? wasm.generate_with_progress(json, progress)
        : wasm.generate(json);
    } catch (thrown) {
      if (isTrap(thrown)) die(thrown);
      else post({ type: 'error', id: request.id, error: toSylvaError(thrown) }, []);
      return;
    }
    try {
      const positions = tree.positions();
      const normals = tree.normals();
      const uvs = tree.uvs();
      const indices = tree.indices();
      const envelope = tree.envelope_lines();
      const markers = tree.markers ? tree.markers() : new Float32Array(0);
      const meta = parseMeta(tree.meta_json());
      const foliage = foliageOf(tree, meta, sentLeafHash);
      sentLeafHash = foliage.leafHash;
      const wind = windOf(tree, positions.length / 3);
      const kind = meta.bark_type ?? 0;
      const bark = barkSent === kind ? undefined : barkOf(wasm, kind);
      barkSent = kind;
      const shade = shadeOf(tree, positions.length / 3);
      post(
        {
          type: 'result',
          id: request.id,
          positions,
          normals,
          uvs,
          indices,
          envelope,
          markers,
          meta,
          foliage,
          wind,
          shade,
          ...(bark ? { bark } : {}),
        },
        [
          ...foliageTransfer(foliage),
          wind.buffer,
          ...(bark ? [bark.color.buffer, bark.normal.buffer, bark.orm.buffer] : []),
          shade.buffer,
          markers.buffer,
          positions.buffer,
          normals.buffer,
          uvs.buffer,
          indices.buffer,
          envelope.buffer,
        ],
      );
    } catch (thrown) {
      if (isTrap(thrown)) die(thrown);
      else post({ type: 'error', id: request.id, error: toSylvaError(thrown) }, []);
    } finally {
      try {
        tree.free();
      } catch {
        // freeing after a trap may fail; the instance is discarded anyway
      }
    }
  };
}
