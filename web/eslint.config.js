// ESLint flat config of the Sylva web app: the shared TypeScript rules
// (scripts/eslint-typescript.mjs) plus react-hooks, no dangerouslySetInnerHTML, and the
// sylva-trees package only through its entries (its package.json `exports`: `sylva-trees`,
// `sylva-trees/core`, `/url`, `/viewer`, `/worker`, `/worker-script`, `/testing`), never by a
// path into its files.
import reactHooks from 'eslint-plugin-react-hooks';
import { typescriptConfig } from '../scripts/eslint-typescript.mjs';

/** A path into packages/ or into the package's sources. */
const DEEP_IMPORT = String.raw`(^|/)packages/|^sylva-trees/src(/|$)`;
const deepImport =
  'Import the sylva-trees package by its entries (package.json `exports`), not its files.';

export default typescriptConfig(import.meta.dirname, ['dist', 'dist-debug'], {
  plugins: { 'react-hooks': reactHooks },
  rules: {
    ...reactHooks.configs.recommended.rules,
    'no-restricted-imports': ['error', { patterns: [{ regex: DEEP_IMPORT, message: deepImport }] }],
    'no-restricted-syntax': [
      'error',
      {
        selector: "JSXAttribute[name.name='dangerouslySetInnerHTML']",
        message: 'Render text as text: no dangerouslySetInnerHTML.',
      },
      {
        selector: `ImportExpression[source.value=/${DEEP_IMPORT.replaceAll('/', '\\/')}/]`,
        message: deepImport,
      },
    ],
  },
});
