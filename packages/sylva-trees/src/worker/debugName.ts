/**
 * The name a generator worker is started with when it should accept the debug messages (in the
 * app's debug build only; see `debug.ts`). A module of its own, so that starting a worker never
 * pulls the test hooks into a bundle.
 */
export const DEBUG_WORKER_NAME = 'sylva-debug';
