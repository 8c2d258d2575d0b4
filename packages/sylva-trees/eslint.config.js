// ESLint flat config of the package: the web app's TypeScript rules
// (scripts/eslint-typescript.mjs), without React.
import { typescriptConfig } from '../../scripts/eslint-typescript.mjs';

export default typescriptConfig(import.meta.dirname, [
  'dist',
  'src/wasm',
  'src/wasm-debug',
  'src/wasm-threads',
  'src/wasm-threads-debug',
]);
