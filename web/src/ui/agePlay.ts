/**
 * The Age timeline's playback, pure: the Age at each moment of a play from a seedling to the
 * Mature Age, on the slider's 0.1-year grid, and how long a play lasts.
 */

/** The first Age a play shows (years). */
export const PLAY_FROM = 1;

/** How long a play of a tree of Mature Age `mature` lasts (ms): 0.2 s a year, 4 to 12 s. */
export function playDuration(mature: number): number {
  return Math.min(12_000, Math.max(4_000, (mature - PLAY_FROM) * 200));
}

/**
 * The Age `elapsed` ms into a play toward `mature`, on the 0.1-year grid (the slider's step):
 * fractional years, so the tree grows without a jump at each year. `done` once it is there.
 */
export function ageAt(elapsed: number, mature: number): { age: number; done: boolean } {
  const duration = playDuration(mature);
  const t = Math.min(1, Math.max(0, elapsed / duration));
  const age = Math.round((PLAY_FROM + (mature - PLAY_FROM) * t) * 10) / 10;
  return { age: Math.min(age, mature), done: t >= 1 };
}
