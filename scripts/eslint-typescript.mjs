// The TypeScript lint rules of the web app (web/eslint.config.js) and the sylva-trees package
// (packages/sylva-trees/eslint.config.js), written once: typescript-eslint type-checked, no
// `any`, type-only imports, no string ever becomes code or HTML (text from share links is only
// ever rendered as text), and the size rule: no file over 500 lines and no function over 120,
// so that every file and function can be read whole (lines as in the editor, blank lines and
// comments included; tests, benches, test helpers and generated files are left out).
import { readdirSync, readFileSync } from 'node:fs';
import { join, relative } from 'node:path';
import js from '@eslint/js';
import globals from 'globals';
import tseslint from 'typescript-eslint';

const asText = 'Render text as text (React children, textContent).';

/** The size rule's limits. */
export const MAX_FILE_LINES = 500;
export const MAX_FUNCTION_LINES = 120;

/**
 * The files under `dir` marked generated (`@generated` or "do not edit" in their first five
 * lines), relative to `dir`: the size rule leaves them out.
 */
export function generatedFiles(dir) {
  const out = [];
  const walk = (d) => {
    for (const entry of readdirSync(d, { withFileTypes: true })) {
      const path = join(d, entry.name);
      if (entry.isDirectory()) {
        if (!['node_modules', 'dist', 'wasm'].includes(entry.name)) walk(path);
      } else if (/\.(m?js|tsx?)$/.test(entry.name)) {
        const head = readFileSync(path, 'utf8').split('\n', 5).join('\n');
        if (/@generated|\bdo not edit\b/i.test(head)) out.push(relative(dir, path));
      }
    }
  };
  walk(dir);
  return out;
}

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
    {
      rules: {
        'max-lines': ['error', { max: MAX_FILE_LINES, skipBlankLines: false, skipComments: false }],
        'max-lines-per-function': [
          'error',
          { max: MAX_FUNCTION_LINES, skipBlankLines: false, skipComments: false, IIFEs: true },
        ],
      },
    },
    {
      files: [
        '**/*.test.{ts,tsx}',
        '**/*.bench.{ts,tsx}',
        '**/{tests,testing,wasm}/**',
        ...generatedFiles(dir),
      ],
      rules: { 'max-lines': 'off', 'max-lines-per-function': 'off' },
    },
    extra,
  );
}
