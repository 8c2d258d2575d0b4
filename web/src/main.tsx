/**
 * Entry point: starts the generator worker first (its wasm downloads and compiles while the
 * app's code loads), then mounts the React app.
 */
import { prestartGenerator } from './createWorker';
import './styles.css';

prestartGenerator();

void import('./boot').then(({ boot }) => {
  const root = document.getElementById('root');
  if (!root) throw new Error('missing #root');
  boot(root);
});
