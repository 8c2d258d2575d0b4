// ESLint flat config for the Node scripts (scripts/*.mjs): the recommended rules with Node globals.
// The web app has its own (web/eslint.config.js, typescript-eslint type-checked).
import js from '@eslint/js';
import globals from 'globals';

export default [
  { ignores: ['node_modules', 'target', 'web', 'packages', 'e2e', 'core-rs'] },
  js.configs.recommended,
  {
    files: ['scripts/**/*.mjs', 'eslint.config.mjs'],
    languageOptions: { ecmaVersion: 2023, sourceType: 'module', globals: { ...globals.node } },
  },
  // Its callbacks run in the page (Playwright's evaluate / waitForFunction).
  {
    files: [
      'scripts/bench-browser.mjs',
      'scripts/bench-edits.mjs',
      'scripts/bench-page.mjs',
      'scripts/bench-forest.mjs',
      'scripts/gallery/*.mjs',
    ],
    languageOptions: { globals: { ...globals.browser } },
  },
];
