/** The docs page: loads the wasm core on the main thread for its registry, then renders. */
import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import { parsePresets, parseRegistry } from 'sylva-trees/core';
import { loadWasmHere } from 'sylva-trees/worker';
import { DocsPage } from './DocsPage';
import { buildDocsModel } from './model';
import '../fonts.css';
import './docs.css';

const rootElement = document.getElementById('root');
if (!rootElement) throw new Error('missing #root');
const root = createRoot(rootElement);

loadWasmHere()
  .then((wasm) => {
    const registry = parseRegistry(wasm.registry_json());
    const model = buildDocsModel(registry, parsePresets(wasm.presets_json()));
    root.render(
      <StrictMode>
        <DocsPage model={model} version={wasm.core_version()} pageHref={window.location.href} />
      </StrictMode>,
    );
  })
  .catch((thrown: unknown) => {
    const message = thrown instanceof Error ? thrown.message : String(thrown);
    root.render(
      <p className="docs-error" role="alert" data-testid="docs-error">
        The parameter reference needs the Sylva core, which could not load: {message}
      </p>,
    );
  });
