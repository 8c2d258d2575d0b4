/** Where Cargo puts the release CLI given the environment (see native-cli.mjs). */
export function cliPath(env?: NodeJS.ProcessEnv): string;
/** Builds the release CLI (a no-op when up to date) and returns its path. */
export function nativeCli(): string;
