// Types of preview-server.mjs for the TypeScript that imports it (the e2e tests).

/** A TCP port nothing listens on now. */
export function freePort(): Promise<number>;

/** `vite preview` of `outDir` (default web/dist) on `port`; `stop()` ends it. */
export function serve(
  port: number,
  options?: { outDir?: string },
): Promise<{ url: string; stop(): Promise<void>; pid: number }>;
