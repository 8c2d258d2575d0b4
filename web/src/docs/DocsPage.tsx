/**
 * The docs page: the parameter reference (from the registry, like the panel), presets, share
 * links, embedding, export and the command line (from the CLI's generated reference). All text
 * is rendered as text.
 */
import { useEffect, type ReactNode } from 'react';
import { CLI_REFERENCE } from './cli';
import { CliSection } from './CliSection';
import type { DocsModel } from './model';

interface Props {
  model: DocsModel;
  version: string;
  /** This page's URL: the examples use absolute URLs next to it. */
  pageHref: string;
}

function Code({ children }: { children: string }) {
  return (
    <pre className="docs-code">
      <code>{children}</code>
    </pre>
  );
}

function Section(props: { id: string; title: string; children: ReactNode }) {
  return (
    <section id={props.id} className="docs-section" data-testid={`docs-${props.id}`}>
      <h2>{props.title}</h2>
      {props.children}
    </section>
  );
}

/** The documentation page. */
export function DocsPage({ model, version, pageHref }: Props) {
  // The target of a deep link (#embedding, #group-...) exists only once rendered.
  useEffect(() => {
    const id = decodeURIComponent(window.location.hash.slice(1));
    if (id) document.getElementById(id)?.scrollIntoView();
  }, []);
  const embedExample = `${new URL('embed.html', pageHref).href}?v=1&seed=7&levels=2&autorotate=1`;
  const scriptUrl = new URL('sylva-tree.js', pageHref).href;
  const origin = new URL(pageHref).origin;
  return (
    <div className="docs">
      <header className="docs-header">
        <h1>Sylva documentation</h1>
        <span className="docs-version">core {version}</span>
        <a href="index.html" className="docs-back" data-testid="docs-back">
          Open the app
        </a>
      </header>

      <nav className="docs-toc" aria-label="Contents">
        <ul>
          <li>
            <a href="#parameters">Parameters</a>
            <ul>
              {model.groups.map((group) => (
                <li key={group.anchor}>
                  <a href={`#${group.anchor}`}>{group.name}</a>
                </li>
              ))}
            </ul>
          </li>
          <li>
            <a href="#presets">Presets</a>
          </li>
          <li>
            <a href="#share">Share links</a>
          </li>
          <li>
            <a href="#embedding">Embedding</a>
          </li>
          <li>
            <a href="#export">Export</a>
          </li>
          <li>
            <a href="#cli">Command line</a>
            <ul>
              {CLI_REFERENCE.commands.map((command) => (
                <li key={command.name}>
                  <a href={`#cli-${command.name}`}>sylva {command.name}</a>
                </li>
              ))}
            </ul>
          </li>
        </ul>
      </nav>

      <main className="docs-main">
        <Section id="parameters" title="Parameters">
          <p>
            All {model.count} parameters in {model.groups.length} groups, in the order of the panel.
            This reference is built from the core&apos;s parameter registry when the page loads, the
            same source as the panel, the share links and their validation. Booleans are 0 or 1,
            options are given by their number.
          </p>
          {model.groups.map((group) => (
            <section
              key={group.anchor}
              id={group.anchor}
              className="docs-group"
              data-group={group.name}
            >
              <h3>{group.name}</h3>
              <table className="docs-params">
                <thead>
                  <tr>
                    <th scope="col">Parameter</th>
                    <th scope="col">Default</th>
                    <th scope="col">Range</th>
                    <th scope="col">Unit</th>
                    <th scope="col">Description</th>
                  </tr>
                </thead>
                <tbody>
                  {group.params.map((p) => (
                    <tr key={p.id} id={`param-${p.id}`} data-param-id={p.id}>
                      <th scope="row">
                        <span className="docs-label">{p.label}</span>
                        <code className="docs-id" data-testid={`doc-id-${p.id}`}>
                          {p.id}
                        </code>
                        <span className="docs-kind">{p.kind}</span>
                      </th>
                      <td data-testid={`doc-default-${p.id}`}>{p.defaultText}</td>
                      <td data-testid={`doc-range-${p.id}`}>{p.rangeText}</td>
                      <td>{p.unit}</td>
                      <td>{p.description}</td>
                    </tr>
                  ))}
                </tbody>
              </table>
            </section>
          ))}
        </Section>

        <Section id="presets" title="Presets">
          <p>
            A preset is a set of values over the defaults; the panel&apos;s preset menu, the
            <code> preset</code> attribute of <code>&lt;sylva-tree&gt;</code> and{' '}
            <code>sylva generate --preset</code> take these names.
          </p>
          <table className="docs-presets">
            <thead>
              <tr>
                <th scope="col">Name</th>
                <th scope="col">Label</th>
                <th scope="col">Description</th>
              </tr>
            </thead>
            <tbody>
              {model.presets.map((p) => (
                <tr key={p.name} data-preset={p.name}>
                  <td>
                    <code>{p.name}</code>
                  </td>
                  <td>{p.label}</td>
                  <td>{p.description}</td>
                </tr>
              ))}
            </tbody>
          </table>
        </Section>

        <Section id="share" title="Share links">
          <p>
            The app&apos;s address always holds the current tree: <code>?v=1</code> followed by the
            parameters that differ from their defaults (<code>id=value</code>, ids from the
            reference above) and, in growth mode, the volume primitives as <code>vol=</code>.
            Opening the link reproduces the same tree (the same content hash). Values outside their
            range or of the wrong type are ignored with a message.
          </p>
        </Section>

        <Section id="embedding" title="Embedding">
          <h3>An iframe</h3>
          <p>
            <code>embed.html</code> takes the same query as a share link and shows only the tree,
            with orbit controls (drag to turn, wheel to zoom) and an <em>Open in Sylva</em> link.
            The app&apos;s <strong>Copy embed code</strong> button (toolbar) copies this snippet for
            the current tree. It is a static page: any static host of the build serves it.
          </p>
          <Code>{`<iframe src="${embedExample}"\n        width="480" height="360" title="Sylva tree" loading="lazy" style="border:0"></iframe>`}</Code>
          <table className="docs-options" data-testid="docs-embed-options">
            <thead>
              <tr>
                <th scope="col">Query key</th>
                <th scope="col">Values</th>
                <th scope="col">Effect</th>
              </tr>
            </thead>
            <tbody>
              <tr>
                <td>
                  <code>v=1</code> and parameter ids
                </td>
                <td>as in a share link</td>
                <td>the tree (missing ids take their default)</td>
              </tr>
              <tr>
                <td>
                  <code>vol</code>
                </td>
                <td>as in a share link</td>
                <td>growth volume primitives</td>
              </tr>
              <tr>
                <td>
                  <code>autorotate</code>
                </td>
                <td>
                  <code>1</code> or <code>0</code>
                </td>
                <td>turns the tree slowly (not when the visitor prefers reduced motion)</td>
              </tr>
              <tr>
                <td>
                  <code>wind</code>
                </td>
                <td>
                  <code>1</code> (default) or <code>0</code>
                </td>
                <td>the tree sways in the wind, or holds still</td>
              </tr>
              <tr>
                <td>
                  <code>bg</code>
                </td>
                <td>
                  <code>transparent</code>, <code>#rrggbb</code>, <code>#rgb</code> or a CSS colour
                  name
                </td>
                <td>
                  the background; transparent drops the sky, ground and fog so the page shows
                  through (write <code>#</code> as <code>%23</code>)
                </td>
              </tr>
            </tbody>
          </table>
          <p>
            A link with an unsupported version or over-long query shows an error in the frame;
            ignored values are listed over the tree.
          </p>

          <h3>
            The <code>&lt;sylva-tree&gt;</code> element
          </h3>
          <p>
            One script tag makes <code>&lt;sylva-tree&gt;</code> available on any page. It draws
            into its own shadow root and canvas, runs the generator in its own worker, and finds the
            worker and the WebAssembly next to the script, wherever that is hosted.
          </p>
          <Code>{`<script type="module" src="${scriptUrl}"></script>\n\n<sylva-tree preset="quaking_aspen" seed="7" params="levels=3&l1_branches=40"\n            autorotate background="transparent"\n            style="width:400px;height:300px"></sylva-tree>`}</Code>
          <table className="docs-options" data-testid="docs-element-attributes">
            <thead>
              <tr>
                <th scope="col">Attribute</th>
                <th scope="col">Value</th>
              </tr>
            </thead>
            <tbody>
              <tr>
                <td>
                  <code>preset</code>
                </td>
                <td>a preset name (see Presets); without it, the defaults</td>
              </tr>
              <tr>
                <td>
                  <code>seed</code>
                </td>
                <td>the random seed (applied last)</td>
              </tr>
              <tr>
                <td>
                  <code>params</code>
                </td>
                <td>
                  parameter values as a share-link query, <code>id=value&amp;id=value</code>{' '}
                  (applied over the preset; may include <code>vol=</code>)
                </td>
              </tr>
              <tr>
                <td>
                  <code>autorotate</code>
                </td>
                <td>present: the tree turns slowly</td>
              </tr>
              <tr>
                <td>
                  <code>wind</code>
                </td>
                <td>
                  absent or <code>on</code>: the tree sways; <code>off</code> or <code>0</code>: it
                  holds still
                </td>
              </tr>
              <tr>
                <td>
                  <code>background</code>
                </td>
                <td>
                  <code>transparent</code>, <code>#rrggbb</code> or a colour name
                </td>
              </tr>
            </tbody>
          </table>
          <p>
            Changing any attribute regenerates the tree (the latest change wins). The element is 300
            × 225 px unless styled. After each tree it has the <code>hash</code> property and{' '}
            <code>data-hash</code> attribute (the content hash), <code>data-status</code> is{' '}
            <code>loading</code>, <code>ready</code> or <code>error</code>, and it fires{' '}
            <code>sylva-tree-ready</code> (<code>event.detail.hash</code>) or{' '}
            <code>sylva-tree-error</code> (<code>event.detail.message</code>); errors are also shown
            inside the element. Removing it stops its worker and frees its GPU memory.
          </p>
          <p>
            From another site the Sylva host must send CORS headers (
            <code>Access-Control-Allow-Origin</code>; most static hosts do) and serve{' '}
            <code>.wasm</code> as <code>application/wasm</code>. If your page has a
            Content-Security-Policy it needs{' '}
            <code>script-src {origin} &apos;wasm-unsafe-eval&apos;</code>,{' '}
            <code>connect-src {origin}</code> and <code>worker-src blob:</code> (the element starts
            its worker through a tiny <code>blob:</code> module that imports the real one, since
            browsers only start same-origin worker scripts).
          </p>
        </Section>

        <Section id="export" title="Export">
          <p>
            The app&apos;s <strong>Export</strong> menu saves the current tree:
          </p>
          <ul>
            <li>
              <strong>PNG screenshot</strong>: the current view at the size of the canvas.
            </li>
            <li>
              <strong>Save preset JSON</strong>: <code>{'{"sylva":1,"params":{...}}'}</code> with
              every parameter value. <strong>Load preset JSON</strong> reads such a file with the
              same validation as a share link; a file with an invalid value is refused with a
              message and the current tree stays.
            </li>
            <li>
              <strong>GLB</strong> (glTF 2.0 binary: bark and instanced leaves, PBR materials,
              embedded textures, wind attributes) and <strong>OBJ + MTL + textures</strong> (one
              zip; leaves baked into the mesh): written by the core&apos;s exporters, the same as{' '}
              <code>sylva generate --out</code>, from the current parameters in a separate worker
              (the view stays responsive). They are offered when the loaded core has the exporters.
            </li>
          </ul>
        </Section>

        <Section id="cli" title="Command line">
          <CliSection />
        </Section>
      </main>
    </div>
  );
}
