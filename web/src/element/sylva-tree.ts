/**
 * `<sylva-tree>`: a Sylva tree on any page, built as the stable script `sylva-tree.js`.
 *
 * ```html
 * <script type="module" src="https://host/sylva-tree.js"></script>
 * <sylva-tree preset="quaking_aspen" seed="7" params="levels=3&l1_branches=40"
 *             autorotate background="transparent" style="width:400px;height:300px"></sylva-tree>
 * ```
 * Attributes: `preset` (a preset name, default: the defaults), `seed`, `params` (a share-link
 * query `id=value&...`, also `vol=`), `autorotate` (present = on), `background` (`transparent`,
 * `#rrggbb` or a colour name). Every change regenerates (the latest wins). After each tree the
 * element has `hash` / `data-hash` and `data-status="ready"`, and fires `sylva-tree-ready`;
 * problems are shown inline and fire `sylva-tree-error`. Removing it stops its worker and frees
 * the GPU resources.
 */
import { TreeEmbed, type EmbedState } from '../embed/TreeEmbed';
import { parseBackground, parseFlag, type Background } from '../embed/options';
import { resolveTreeAttributes } from './attributes';
import elementCss from './element.css?inline';
import statusCss from '../embed/status.css?inline';
import { elementWorkerFactory } from './workerFactory';

const TREE_ATTRIBUTES = ['preset', 'seed', 'params'] as const;

let sheet: CSSStyleSheet | null = null;

/** The shadow-root stylesheet, shared by every instance. */
function styleSheet(): CSSStyleSheet {
  if (!sheet) {
    sheet = new CSSStyleSheet();
    sheet.replaceSync(elementCss + statusCss);
  }
  return sheet;
}

/** The `<sylva-tree>` custom element. */
export class SylvaTreeElement extends HTMLElement {
  static readonly observedAttributes = [...TREE_ATTRIBUTES, 'autorotate', 'background', 'wind'];

  private readonly view: HTMLDivElement;
  private embed: TreeEmbed | null = null;
  private regenerateQueued = false;

  constructor() {
    super();
    const root = this.attachShadow({ mode: 'open' });
    root.adoptedStyleSheets = [styleSheet()];
    this.view = document.createElement('div');
    this.view.className = 'view';
    this.view.part.add('view');
    root.append(this.view);
  }

  /** Content hash of the tree shown for the current attributes ('' until it is ready). */
  get hash(): string {
    const state = this.embed?.current;
    return state?.status === 'ready' ? state.hash : '';
  }

  /** `loading`, `ready` or `error` (`idle` while not in a document). */
  get status(): EmbedState['status'] | 'idle' {
    return this.embed?.current.status ?? 'idle';
  }

  connectedCallback(): void {
    if (this.embed) return;
    this.embed = new TreeEmbed(this.view, {
      workerFactory: elementWorkerFactory,
      background: this.background().value,
      autorotate: this.autorotateOn(),
      wind: this.windOn(),
      onState: (state) => this.onState(state),
    });
    this.regenerate();
  }

  disconnectedCallback(): void {
    // Moving the element (remove + insert in one task) must not restart the worker.
    queueMicrotask(() => {
      if (this.isConnected || !this.embed) return;
      this.embed.dispose();
      this.embed = null;
      delete this.dataset.status;
      delete this.dataset.hash;
    });
  }

  attributeChangedCallback(name: string, oldValue: string | null, value: string | null): void {
    if (oldValue === value || !this.embed) return;
    if (name === 'autorotate') this.embed.setAutorotate(this.autorotateOn());
    else if (name === 'wind') this.embed.setWind(this.windOn());
    else if (name === 'background') {
      this.embed.setBackground(this.background().value);
      this.regenerate(); // refreshes the notices
    } else this.regenerate();
  }

  /** Generates the tree of the current attributes (several changes in one task: one request). */
  regenerate(): void {
    if (this.regenerateQueued) return;
    this.regenerateQueued = true;
    queueMicrotask(() => {
      this.regenerateQueued = false;
      const embed = this.embed;
      if (!embed) return;
      const attributes = {
        preset: this.getAttribute('preset'),
        seed: this.getAttribute('seed'),
        params: this.getAttribute('params'),
      };
      const backgroundMessage = this.background().message;
      embed.show(({ registry, presets }) => {
        const resolved = resolveTreeAttributes(registry, presets, attributes);
        if (backgroundMessage) resolved.messages.unshift(backgroundMessage);
        return resolved;
      });
    });
  }

  /** `wind` absent or on: the tree sways; `wind="0"`/`"off"` holds it still. */
  private windOn(): boolean {
    const raw = this.getAttribute('wind');
    return raw === null ? true : (parseFlag(raw) ?? true);
  }

  private autorotateOn(): boolean {
    return parseFlag(this.getAttribute('autorotate')) ?? true;
  }

  private background(): { value: Background; message: string | null } {
    const parsed = parseBackground(this.getAttribute('background'));
    if (typeof parsed !== 'string') return { value: parsed, message: null };
    return { value: { kind: 'default' }, message: `Ignored the background attribute: ${parsed}.` };
  }

  private onState(state: EmbedState): void {
    this.dataset.status = state.status;
    if (state.status === 'ready') {
      this.dataset.hash = state.hash;
      this.dispatchEvent(
        new CustomEvent('sylva-tree-ready', { detail: { hash: state.hash }, bubbles: true }),
      );
    } else if (state.status === 'error') {
      delete this.dataset.hash;
      this.dispatchEvent(
        new CustomEvent('sylva-tree-error', { detail: { message: state.message }, bubbles: true }),
      );
    }
  }
}

declare global {
  interface HTMLElementTagNameMap {
    'sylva-tree': SylvaTreeElement;
  }
}

if (!customElements.get('sylva-tree')) customElements.define('sylva-tree', SylvaTreeElement);
