// ESLint flat config of the Sylva web app: the shared TypeScript rules
// (scripts/eslint-typescript.mjs) plus react-hooks and no dangerouslySetInnerHTML.
import reactHooks from 'eslint-plugin-react-hooks';
import { typescriptConfig } from '../scripts/eslint-typescript.mjs';

export default typescriptConfig(import.meta.dirname, ['dist'], {
  plugins: { 'react-hooks': reactHooks },
  rules: {
    ...reactHooks.configs.recommended.rules,
    'no-restricted-syntax': [
      'error',
      {
        selector: "JSXAttribute[name.name='dangerouslySetInnerHTML']",
        message: 'Render text as text: no dangerouslySetInnerHTML.',
      },
    ],
  },
});
