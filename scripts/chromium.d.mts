/** Types of chromium.mjs (imported by the TypeScript Playwright config). */
export declare function chromiumPath(env?: Record<string, string | undefined>): string;
export declare const CHROMIUM_ARGS: string[];
