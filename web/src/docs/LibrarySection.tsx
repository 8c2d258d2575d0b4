/** The docs page's section on the `sylva-trees` npm package: a Sylva tree in your own scene. */
import { Code, DocsTable, Section } from './DocsParts';
import { LIBRARY_API, LIBRARY_EXAMPLE } from './library';

/** See the module comment. */
export function LibrarySection() {
  return (
    <Section id="library" title="In your own three.js scene">
      <p>
        The <code>sylva-trees</code> package puts a Sylva tree into <em>your</em> scene, with your
        renderer, camera, lights and render loop: <code>npm install sylva-trees three</code>{' '}
        (three.js r160 or newer). It is ES modules with TypeScript declarations; each tree generates
        in a worker of its own, and the worker and the wasm core are found next to the module, so
        nothing has to be copied by hand.
      </p>
      <Code>{LIBRARY_EXAMPLE}</Code>
      <DocsTable
        className="docs-options"
        testId="docs-library-api"
        columns={['Call', 'What it does']}
      >
        {LIBRARY_API.map((row) => (
          <tr key={row.call}>
            <td>
              <code>{row.call}</code>
            </td>
            <td>{row.what}</td>
          </tr>
        ))}
      </DocsTable>
      <p>
        Serve the package from your own site (a bundler such as Vite does it; without one, copy its{' '}
        <code>dist/</code> folder and point an import map at it): browsers start workers only from
        the page&apos;s own origin. With the Vite dev server, add{' '}
        <code>{"optimizeDeps: { exclude: ['sylva-trees'] }"}</code>. The package&apos;s README has a
        complete page with two trees, lights and a render loop.
      </p>
    </Section>
  );
}
