/**
 * The generator worker's test hooks: none. The app's debug build (web/vite.config.ts,
 * `debugBuild`) resolves this module to `debug.ts`, whose `debugHooks` answer the debug
 * messages; the shipped worker keeps this `null` and refuses them.
 */
import type { DebugHooks } from './debug';

/** The worker's test hooks (none in a shipped build). */
export const debugHooks: DebugHooks | null = null;
