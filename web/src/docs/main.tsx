/** The docs page: loads the wasm core on the main thread for its registry, then renders. */
import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import { parsePresets, parseRegistry } from '../../../packages/sylva-trees/src/core/parse';
import init, {
  core_version,
  presets_json,
  registry_json,
} from '../../../packages/sylva-trees/src/wasm/sylva_wasm.js';
import { DocsPage } from './DocsPage';
import { buildDocsModel } from './model';
import '../fonts.css';
import './docs.css';

const rootElement = document.getElementById('root');
if (!rootElement) throw new Error('missing #root');
const root = createRoot(rootElement);

init()
  .then(() => {
    const model = buildDocsModel(parseRegistry(registry_json()), parsePresets(presets_json()));
    root.render(
      <StrictMode>
        <DocsPage model={model} version={core_version()} pageHref={window.location.href} />
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
