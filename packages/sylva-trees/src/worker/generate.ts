/**
 * Generate requests over the core's incremental session (one per worker): the session reruns
 * only the stages an edit touches, the answer carries only the arrays that changed since the
 * previous answer, and the content hash follows in its own message once the buffers are out.
 * No Worker globals: the scheduling of the hash is injected, so this is tested in Node.
 */
import { parseMeta } from '../core/parse';
import type {
  BarkTextureBuffers,
  EndGrainBuffers,
  Params,
  TreeMeta,
  TreeUpdate,
  WasmApi,
  WasmSession,
} from '../core/types';
import { coreInput } from '../core/editsJson';
import { pickBoxes } from '../core/pickBoxes';
import { volumeToCore } from '../core/volumes';
import type { GenerateRequest, WorkerResponse } from './protocol';
import { meanTint, organsOf, organViews } from './organs';

/** Sends a response, transferring the given buffers. */
export type Post = (message: WorkerResponse, transfer: Transferable[]) => void;

/** Runs `task` later (after the current message), returning a function that cancels it. */
export type Defer = (task: () => void) => () => void;

/** The worker's default: a zero-delay timer (a queued request runs first and cancels it). */
export const deferToTimer: Defer = (task) => {
  const timer = setTimeout(task, 0);
  return () => clearTimeout(timer);
};

/**
 * Longest the full bark may take (by the last full sweep) before a drag is answered with a
 * preview bark (ms). The default tree's bark takes about 8 ms in wasm on a 2-core machine, its
 * preview under 2: with the skeleton and the leaves that keeps a drag inside a frame.
 */
export const PREVIEW_BUDGET_MS = 4;

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

/** Edge length of the baked end grain (texels): a cut face is looked at up close. */
export const END_GRAIN_TEXTURE_SIZE = 512;

/** The core's end grain of bark type `kind`, or undefined when this wasm build has none. */
export function endGrainOf(wasm: WasmApi, kind = 0): EndGrainBuffers | undefined {
  if (typeof wasm.end_grain_maps !== 'function') return undefined;
  const maps = wasm.end_grain_maps(kind, END_GRAIN_TEXTURE_SIZE);
  const size = Math.round(Math.sqrt(maps.length / 8));
  if (size < 1 || size * size * 8 !== maps.length) return undefined;
  const n = size * size * 4;
  // Two copies, so that each map's buffer can be transferred on its own.
  return { size, kind, color: maps.slice(0, n), normal: maps.slice(n, 2 * n) };
}

/** Whether the tree of `meta` has cut faces (a `cut_face` group with triangles). */
export function hasCutFaces(meta: TreeMeta): boolean {
  return meta.groups.some((g) => g.material === 'cut_face' && g.count > 0);
}

/**
 * The tree's wind data (8 floats per vertex), read defensively: empty when its length does
 * not match the vertex count.
 */
export function windOf(wind: Float32Array, vertices: number): Float32Array {
  return wind.length === vertices * 8 && vertices > 0 ? wind : new Float32Array(0);
}

/** The arrays of `update`, for the transfer list. */
export function transferOf(update: TreeUpdate): Transferable[] {
  const views: ArrayBufferView[] = [];
  const b = update.bark;
  if (b) views.push(b.positions, b.normals, b.uvs, b.indices, b.wind);
  if (b?.pick) views.push(b.pick);
  if (update.envelope) views.push(update.envelope);
  if (update.markers) views.push(update.markers);
  if (update.instances) views.push(update.instances.matrices, update.instances.colors);
  views.push(...organViews(update.organs));
  const l = update.leafMesh;
  if (l) views.push(l.positions, l.normals, l.uvs, l.indices);
  if (update.leafTexture) views.push(update.leafTexture.rgba);
  if (update.barkTextures) {
    const t = update.barkTextures;
    views.push(t.color, t.normal, t.orm);
  }
  if (update.endGrain) views.push(update.endGrain.color, update.endGrain.normal);
  if (update.shade) views.push(update.shade);
  return [...new Set(views.map((v) => v.buffer as ArrayBuffer))];
}

/** Settings of a [`SessionGenerator`]. */
export interface SessionGeneratorOptions {
  /** How the hash is scheduled after a result (default: a zero-delay timer). */
  defer?: Defer;
  /** Bark time above which a drag gets a preview (ms; default [`PREVIEW_BUDGET_MS`]). */
  previewBudgetMs?: number;
  /** Called with what a deferred hash computation threw (a trap kills the worker). */
  onDeferredThrow?: (thrown: unknown) => void;
}

/** Answers generate requests; throws what the core throws (the caller tells traps apart). */
export class SessionGenerator {
  private readonly session: WasmSession;
  /** Leaf shape whose texture the main thread has ('' = none). */
  private sentLeafHash = '';
  /** The bark type whose maps the main thread has (null: none yet). */
  private barkSent: number | null = null;
  /** Bark maps baked ahead by [`SessionGenerator.prime`], not sent yet. */
  private barkBaked: BarkTextureBuffers | null = null;
  /** The bark type whose end grain the main thread has (null: none yet, baked at the first cut). */
  private grainSent: number | null = null;
  /** Whether a result went out: the first one carries every array, whatever changed. */
  private sentAny = false;
  /** Result whose hash is still to be posted, and the cancel of its scheduled task. */
  private hashOwed: number | null = null;
  private cancelHash: (() => void) | null = null;

  private readonly defer: Defer;
  private readonly previewBudgetMs: number;
  private readonly onDeferredThrow: (thrown: unknown) => void;

  constructor(
    private readonly wasm: WasmApi,
    private readonly post: Post,
    options: SessionGeneratorOptions = {},
  ) {
    this.session = new wasm.Session();
    this.defer = options.defer ?? deferToTimer;
    this.previewBudgetMs = options.previewBudgetMs ?? PREVIEW_BUDGET_MS;
    this.onDeferredThrow = options.onDeferredThrow ?? (() => undefined);
  }

  /** Generates the tree of `request` and posts the changed arrays (then, later, the hash). */
  handle(request: GenerateRequest): void {
    this.cancelHash?.();
    this.cancelHash = null;
    const input = coreInput(request.params, request.volumes?.map(volumeToCore), request.edits);
    let lastStep = -1;
    // Progress while growing: at most 50 messages per request (every 2 %).
    const progress = (fraction: number): void => {
      const step = Math.floor(fraction * 50);
      if (step === lastStep) return;
      lastStep = step;
      this.post({ type: 'progress', id: request.id, fraction }, []);
    };
    const budget = request.preview ? this.previewBudgetMs : -1;
    let meta: TreeMeta;
    try {
      meta = parseMeta(this.session.update(JSON.stringify(input), budget, progress));
    } catch (thrown) {
      // The previous tree stays on screen: it still needs its hash if a newer request took it.
      this.postOwedHash();
      throw thrown;
    }
    const update = this.collect(meta, request.endGrain === true);
    this.post({ type: 'result', id: request.id, ...update }, transferOf(update));
    this.hashOwed = meta.preview ? null : request.id;
    if (this.hashOwed !== null) {
      this.cancelHash = this.defer(() => {
        this.cancelHash = null;
        try {
          this.postOwedHash();
        } catch (thrown) {
          this.onDeferredThrow(thrown);
        }
      });
    }
  }

  /**
   * Generates `params` into the session without posting anything (a warm-up): the first
   * request then reruns only what differs, and still gets every array.
   */
  prime(params: Params): void {
    const meta = parseMeta(this.session.update(JSON.stringify(params), -1));
    // Its bark maps too (about 50 ms): the first result then only copies arrays out.
    this.barkBaked = barkOf(this.wasm, meta.bark_type) ?? null;
  }

  /** Forgets the cached stages (the next request generates cold). */
  clear(): void {
    this.barkBaked = null;
    this.cancelHash?.();
    this.cancelHash = null;
    this.hashOwed = null;
    this.session.clear();
  }

  private postOwedHash(): void {
    const id = this.hashOwed;
    this.hashOwed = null;
    if (id === null) return;
    const hash = this.session.hash();
    if (hash) this.post({ type: 'hash', id, hash }, []);
  }

  /**
   * The arrays `meta.changes` names, copied out of the module (one copy each); the end grain
   * too when the tree has cut faces or `grain` asks for it, unless already sent for its type.
   */
  private collect(meta: TreeMeta, grain: boolean): TreeUpdate {
    const s = this.session;
    const all = {
      skeleton: true,
      bark: true,
      placements: true,
      leaf_mesh: true,
      leaf: true,
      shade: true,
    };
    const changes = this.sentAny ? (meta.changes ?? all) : all;
    this.sentAny = true;
    const update: TreeUpdate = { meta };
    if (changes.bark) {
      const positions = s.positions();
      const indices = s.indices();
      update.bark = {
        positions,
        normals: s.normals(),
        uvs: s.uvs(),
        indices,
        wind: windOf(s.wind(), meta.vertices),
        // In the core where it can (a third of the JavaScript's time: the default tree's
        // 2.7 ms before, 0.8 now).
        pick: s.pick_boxes?.() ?? pickBoxes(positions, indices),
      };
    }
    if (changes.skeleton) {
      update.envelope = s.envelope_lines();
      update.markers = s.markers();
    }
    if (changes.placements) {
      const colors = s.leaf_colors();
      update.instances = { matrices: s.leaf_matrices(), colors };
      // The core's placements change covers the organ sets and the fallen leaves too.
      update.organs = organsOf(s);
      update.leafTint = meanTint(colors, colors.length / 3 - (s.fallen?.() ?? 0));
    }
    if (changes.leaf_mesh) {
      update.leafMesh = {
        positions: s.leaf_positions(),
        normals: s.leaf_normals(),
        uvs: s.leaf_uvs(),
        indices: s.leaf_indices(),
      };
    }
    const leafHash = meta.leaf_texture ? meta.leaf_hash : '';
    if (leafHash !== this.sentLeafHash && meta.leaf_texture) {
      const [width, height] = meta.leaf_texture;
      const rgba = s.leaf_texture();
      if (rgba.length === width * height * 4) update.leafTexture = { width, height, rgba };
    }
    // A bare tree sent no texture: the next leafy tree must send one.
    this.sentLeafHash = leafHash;
    // The bark maps go out with the first result and again when the bark type changes.
    const kind = meta.bark_type;
    if (this.barkSent !== kind) {
      this.barkSent = kind;
      const baked = this.barkBaked;
      this.barkBaked = null;
      const bark = baked?.kind === kind ? baked : barkOf(this.wasm, kind);
      if (bark) update.barkTextures = bark;
    }
    // The end grain once a tree has cut faces or the request asks for it ahead of a cut (about
    // 0.1 s to bake the first time in the browser), again for a new type.
    if (this.grainSent !== kind && (grain || hasCutFaces(meta))) {
      this.grainSent = kind;
      const grain = endGrainOf(this.wasm, kind);
      if (grain) update.endGrain = grain;
    }
    // The occlusion belongs to the bark it was computed for: sent with every new bark.
    if (changes.bark || changes.shade) update.shade = s.shade();
    return update;
  }
}
