/**
 * Entry point: starts the generator worker first (its wasm downloads and compiles while the
 * app's code loads; a debug worker on a debug page), then mounts the React app.
 */
import { debugMode } from './app/debugHook';
import { prestartGenerator } from './createWorker';
import './fonts.css';
import './styles.css';

prestartGenerator({ debug: debugMode() });

void import('./boot').then(({ boot }) => {
  const root = document.getElementById('root');
  if (!root) throw new Error('missing #root');
  boot(root);
});
