/** The built core's registry and presets (vite.config.ts, `catalog`). */
declare module 'virtual:sylva-catalog' {
  export const registryJson: string;
  export const presetsJson: string;
  export const coreVersion: string;
}
