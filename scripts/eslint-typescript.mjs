// The TypeScript lint rules of the web app (web/eslint.config.js) and the sylva-trees package
// (packages/sylva-trees/eslint.config.js), written once: typescript-eslint type-checked, no
// `any`, type-only imports, and no string ever becomes code or HTML (text from share links is
// only ever rendered as text).
import js from '@eslint/js';
import globals from 'globals';
import tseslint from 'typescript-eslint';

const asText = 'Render text as text (React children, textContent).';

/**
 * The flat config of the TypeScript project in `dir` (its tsconfig there), leaving out `ignores`
 * (and the config file itself); `extra` (plugins, more rules) comes last.
 */
export function typescriptConfig(dir, ignores, extra = {}) {
  return tseslint.config(
    { ignores: [...ignores, 'eslint.config.js'] },
    js.configs.recommended,
    ...tseslint.configs.recommendedTypeChecked,
    {
      languageOptions: {
        ecmaVersion: 2022,
        globals: { ...globals.browser },
        parserOptions: { projectService: true, tsconfigRootDir: dir },
      },
      rules: {
        '@typescript-eslint/no-explicit-any': 'error',
        '@typescript-eslint/consistent-type-imports': 'error',
        'no-eval': 'error',
        'no-new-func': 'error',
        'no-restricted-properties': [
          'error',
          { property: 'innerHTML', message: asText },
          { property: 'outerHTML', message: asText },
          { property: 'insertAdjacentHTML', message: 'Build DOM nodes instead of HTML strings.' },
          { object: 'document', property: 'write', message: 'Never write HTML strings.' },
        ],
      },
    },
    extra,
  );
}
