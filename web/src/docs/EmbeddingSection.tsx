/** The docs page's embedding section: the iframe and the `<sylva-tree>` element. */
import type { ReactNode } from 'react';
import { Code, DocsTable, Section } from './DocsParts';

/** A table row: an option's name (as code), then its cells. */
function OptionRow({ name, children }: { name: string; children: ReactNode }) {
  return (
    <tr>
      <td>
        <code>{name}</code>
      </td>
      {children}
    </tr>
  );
}

/** See the module comment; the examples use absolute URLs next to `pageHref`. */
export function EmbeddingSection({ pageHref }: { pageHref: string }) {
  return (
    <Section id="embedding" title="Embedding">
      <IframeDocs pageHref={pageHref} />
      <ElementDocs pageHref={pageHref} />
    </Section>
  );
}

/** `embed.html` in an iframe, and its query keys. */
function IframeDocs({ pageHref }: { pageHref: string }) {
  const embedExample = `${new URL('embed.html', pageHref).href}?v=1&seed=7&levels=2&autorotate=1`;
  return (
    <>
      <h3>An iframe</h3>
      <p>
        <code>embed.html</code> takes the same query as a share link and shows only the tree, with
        orbit controls (drag to turn, wheel to zoom) and an <em>Open in Sylva</em> link. The
        app&apos;s <strong>Copy embed code</strong> button (toolbar) copies this snippet for the
        current tree. It is a static page: any static host of the build serves it.
      </p>
      <Code>{`<iframe src="${embedExample}"\n        width="480" height="360" title="Sylva tree" loading="lazy" style="border:0"></iframe>`}</Code>
      <DocsTable
        className="docs-options"
        testId="docs-embed-options"
        columns={['Query key', 'Values', 'Effect']}
      >
        <tr>
          <td>
            <code>v=1</code> and parameter ids
          </td>
          <td>as in a share link</td>
          <td>the tree (missing ids take their default)</td>
        </tr>
        <OptionRow name="vol">
          <td>as in a share link</td>
          <td>growth volume primitives</td>
        </OptionRow>
        <OptionRow name="autorotate">
          <td>
            <code>1</code> or <code>0</code>
          </td>
          <td>turns the tree slowly (not when the visitor prefers reduced motion)</td>
        </OptionRow>
        <OptionRow name="wind">
          <td>
            <code>1</code> (default) or <code>0</code>
          </td>
          <td>the tree sways in the wind, or holds still</td>
        </OptionRow>
        <OptionRow name="bg">
          <td>
            <code>transparent</code>, <code>#rrggbb</code>, <code>#rgb</code> or a CSS colour name
          </td>
          <td>
            the background; transparent drops the sky, ground and fog so the page shows through
            (write <code>#</code> as <code>%23</code>)
          </td>
        </OptionRow>
      </DocsTable>
      <p>
        A link with an unsupported version or over-long query shows an error in the frame; ignored
        values are listed over the tree.
      </p>
    </>
  );
}

/** The `<sylva-tree>` element: its script, attributes, events and what a host must allow. */
function ElementDocs({ pageHref }: { pageHref: string }) {
  const scriptUrl = new URL('sylva-tree.js', pageHref).href;
  const origin = new URL(pageHref).origin;
  return (
    <>
      <h3>
        The <code>&lt;sylva-tree&gt;</code> element
      </h3>
      <p>
        One script tag makes <code>&lt;sylva-tree&gt;</code> available on any page. It draws into
        its own shadow root and canvas, runs the generator in its own worker, and finds the worker
        and the WebAssembly next to the script, wherever that is hosted.
      </p>
      <Code>{`<script type="module" src="${scriptUrl}"></script>\n\n<sylva-tree preset="quaking_aspen" seed="7" params="levels=3&l1_branches=40"\n            autorotate background="transparent"\n            style="width:400px;height:300px"></sylva-tree>`}</Code>
      <DocsTable
        className="docs-options"
        testId="docs-element-attributes"
        columns={['Attribute', 'Value']}
      >
        <OptionRow name="preset">
          <td>a preset name (see Presets); without it, the defaults</td>
        </OptionRow>
        <OptionRow name="seed">
          <td>the random seed (applied last)</td>
        </OptionRow>
        <OptionRow name="params">
          <td>
            parameter values as a share-link query, <code>id=value&amp;id=value</code> (applied over
            the preset; may include <code>vol=</code>)
          </td>
        </OptionRow>
        <OptionRow name="autorotate">
          <td>present: the tree turns slowly</td>
        </OptionRow>
        <OptionRow name="wind">
          <td>
            absent or <code>on</code>: the tree sways; <code>off</code> or <code>0</code>: it holds
            still
          </td>
        </OptionRow>
        <OptionRow name="background">
          <td>
            <code>transparent</code>, <code>#rrggbb</code> or a colour name
          </td>
        </OptionRow>
      </DocsTable>
      <p>
        Changing any attribute regenerates the tree (the latest change wins). The element is 300 ×
        225 px unless styled. After each tree it has the <code>hash</code> property and{' '}
        <code>data-hash</code> attribute (the content hash), <code>data-status</code> is{' '}
        <code>loading</code>, <code>ready</code> or <code>error</code>, and it fires{' '}
        <code>sylva-tree-ready</code> (<code>event.detail.hash</code>) or{' '}
        <code>sylva-tree-error</code> (<code>event.detail.message</code>); errors are also shown
        inside the element. Removing it stops its worker and frees its GPU memory.
      </p>
      <p>
        From another site the Sylva host must send CORS headers (
        <code>Access-Control-Allow-Origin</code>; most static hosts do) and serve <code>.wasm</code>{' '}
        as <code>application/wasm</code>. If your page has a Content-Security-Policy it needs{' '}
        <code>script-src {origin} &apos;wasm-unsafe-eval&apos;</code>,{' '}
        <code>connect-src {origin}</code> and <code>worker-src blob:</code> (the element starts its
        worker through a tiny <code>blob:</code> module that imports the real one, since browsers
        only start same-origin worker scripts).
      </p>
    </>
  );
}
