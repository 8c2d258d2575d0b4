// dependency-cruiser config of the web app's and the sylva-trees package's lint: no import cycle
// in their sources, type-only imports included (`tsPreCompilationDeps`: a type import ties two
// modules together as much as a value import does, and ESLint's import-x/no-cycle skips them).
// Run from a workspace as `depcruise --config ../scripts/depcruise.mjs src` (see its `lint`).
export default {
  forbidden: [
    {
      name: 'no-cycle',
      severity: 'error',
      comment: 'An import cycle: move what both modules need into a module of its own.',
      from: {},
      to: { circular: true },
    },
  ],
  options: {
    tsPreCompilationDeps: true,
    doNotFollow: { path: 'node_modules' },
    // The package's entries resolve to source, as in the app's Vite and TypeScript configs.
    enhancedResolveOptions: {
      conditionNames: ['sylva-source', 'import', 'types', 'default'],
      exportsFields: ['exports'],
      extensions: ['.ts', '.tsx', '.js', '.mjs'],
    },
  },
};
