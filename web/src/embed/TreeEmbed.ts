/**
 * A bare tree view for embedding (the embed page and `<sylva-tree>`): the app's TreeViewer and
 * latest-wins generation scheduler over the wasm worker, plus autorotate, a background option
 * and a status line (loading, errors) drawn as text over the view. No React.
 */
import { describeError } from '../core/describeError';
import type { Edit, Params, VolumePrimitive } from 'sylva-trees/core';
import { TreeViewer } from '../viewer/TreeViewer';
import { GenerationScheduler, type GeneratorFactory, type ReadyInfo } from 'sylva-trees/worker';
import type { Background } from './options';

/** What to generate once the registry is known (or why nothing can be generated). */
export interface TreeSource {
  params: Params;
  volumes: VolumePrimitive[];
  /** The hand edits (a share link's `e=`; absent or empty: none). */
  edits?: Edit[];
  /** Ignored values, shown as notices over the tree. */
  messages: string[];
  /** Shown as an error instead of a tree. */
  fatal: string | null;
}

/** The embed's state, reported after every change. */
export type EmbedState =
  | { status: 'loading' }
  | { status: 'ready'; hash: string; messages: string[] }
  | { status: 'error'; message: string; messages: string[] };

/** Settings of a TreeEmbed. */
export interface TreeEmbedOptions {
  workerFactory: GeneratorFactory;
  background: Background;
  autorotate: boolean;
  /** Wind animation on (default) or off. */
  wind?: boolean;
  onState?(state: EmbedState): void;
}

/** The sky of the app viewer when no background option is given. */
const DEFAULT_SKY = '#dce6ec';

/** Owns a TreeViewer, a scheduler (one worker) and the status text in `container`. */
export class TreeEmbed {
  readonly viewer: TreeViewer;
  private readonly scheduler: GenerationScheduler;
  private readonly status: HTMLDivElement;
  private info: ReadyInfo | null = null;
  private resolve: ((info: ReadyInfo) => TreeSource) | null = null;
  private latestId = 0;
  private messages: string[] = [];
  private state: EmbedState = { status: 'loading' };
  private autorotate = false;
  private frameId = 0;
  private lastTime: number | null = null;
  private disposed = false;

  constructor(
    container: HTMLElement,
    private readonly options: TreeEmbedOptions,
  ) {
    this.viewer = new TreeViewer(container, { alpha: true });
    this.status = document.createElement('div');
    this.status.className = 'sylva-status';
    this.status.setAttribute('role', 'status');
    this.status.dataset.testid = 'embed-status';
    container.appendChild(this.status);
    this.setBackground(options.background);
    this.setAutorotate(options.autorotate);
    this.setWind(options.wind ?? true);
    this.render();
    this.scheduler = new GenerationScheduler(options.workerFactory, {
      onReady: (info) => {
        const first = this.info === null;
        this.info = info;
        if (first) this.requestNow();
      },
      onResult: (result) => {
        this.viewer.apply(result, true);
      },
      // Ready once the latest tree's hash (which follows its buffers) is known.
      onHash: (hash, id) => {
        this.viewer.setHash(hash);
        if (id !== this.latestId) return;
        this.setState({ status: 'ready', hash, messages: this.messages });
      },
      onError: (error, id) => {
        if (id !== null && id !== this.latestId) return;
        const registry = this.info?.registry ?? [];
        this.setState({
          status: 'error',
          message: describeError(error, registry),
          messages: this.messages,
        });
      },
      onBusyChange: () => undefined,
    });
  }

  /** The current state. */
  get current(): EmbedState {
    return this.state;
  }

  /** The registry and presets once the worker is ready (null before). */
  get ready(): ReadyInfo | null {
    return this.info;
  }

  /** Shows the tree `resolve` gives for the registry (now, or when the worker is ready). */
  show(resolve: (info: ReadyInfo) => TreeSource): void {
    this.resolve = resolve;
    if (this.info) this.requestNow();
  }

  /** Turns the slow turntable rotation on or off (off when the user prefers reduced motion). */
  setAutorotate(on: boolean): void {
    const reduce =
      typeof matchMedia === 'function' && matchMedia('(prefers-reduced-motion: reduce)').matches;
    this.autorotate = on && !reduce;
    const orbit = this.viewer.overlayHost().orbit;
    orbit.autoRotate = this.autorotate;
    orbit.autoRotateSpeed = 1.5;
    if (this.autorotate && this.frameId === 0 && !this.disposed) {
      this.lastTime = null;
      this.frameId = requestAnimationFrame((t) => this.spin(t));
    }
  }

  /** Whether the view is turning. */
  get rotating(): boolean {
    return this.autorotate;
  }

  /** Turns the wind animation on or off. */
  setWind(on: boolean): void {
    this.viewer.wind.set({ enabled: on });
  }

  /** Sets the background: the app's sky, a colour, or transparent (no sky, ground or fog). */
  setBackground(background: Background): void {
    if (background.kind === 'transparent') this.viewer.setBackground(null);
    else this.viewer.setBackground(background.kind === 'color' ? background.color : DEFAULT_SKY);
  }

  /** Stops the worker and frees every GPU resource. */
  dispose(): void {
    this.disposed = true;
    if (this.frameId !== 0) cancelAnimationFrame(this.frameId);
    this.frameId = 0;
    this.scheduler.dispose();
    this.viewer.dispose();
    this.status.remove();
  }

  private requestNow(): void {
    if (!this.info || !this.resolve || this.disposed) return;
    let source: TreeSource;
    try {
      source = this.resolve(this.info);
    } catch (thrown) {
      const message = thrown instanceof Error ? thrown.message : String(thrown);
      source = { params: {}, volumes: [], messages: [], fatal: message };
    }
    this.messages = source.messages;
    if (source.fatal !== null) {
      // A newer request supersedes whatever is in flight: its result is no longer wanted.
      this.latestId = -1;
      this.setState({ status: 'error', message: source.fatal, messages: source.messages });
      return;
    }
    const edits = source.edits?.length ? { edits: source.edits } : {};
    this.latestId = this.scheduler.request(source.params, source.volumes, edits);
    this.setState({ status: 'loading' });
  }

  private spin(time: number): void {
    this.frameId = 0;
    if (!this.autorotate || this.disposed) return;
    const dt = this.lastTime === null ? 0 : Math.min((time - this.lastTime) / 1000, 0.1);
    this.lastTime = time;
    // Moves the camera and fires `change`, which requests a render.
    this.viewer.overlayHost().orbit.update(dt);
    this.frameId = requestAnimationFrame((t) => this.spin(t));
  }

  private setState(state: EmbedState): void {
    this.state = state;
    this.render();
    this.options.onState?.(state);
  }

  /** Writes the status text (as text nodes only). */
  private render(): void {
    const lines: string[] = [];
    let kind = 'info';
    if (this.state.status === 'loading') lines.push('Growing the tree…');
    if (this.state.status === 'error') {
      kind = 'error';
      lines.push(this.state.message);
    }
    if (this.state.status !== 'loading') lines.push(...this.state.messages);
    if (this.state.status === 'ready' && lines.length > 0) kind = 'notice';
    this.status.replaceChildren(
      ...lines.map((line) => {
        const p = document.createElement('p');
        p.textContent = line;
        return p;
      }),
    );
    this.status.dataset.kind = kind;
    this.status.setAttribute('role', kind === 'info' ? 'status' : 'alert');
    this.status.hidden = lines.length === 0;
  }
}
