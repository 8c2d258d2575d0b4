/** The Age timeline's playback times. */
import { describe, expect, it } from 'vitest';
import { ageAt, PLAY_FROM, playDuration } from './agePlay';

describe('Age playback', () => {
  it('runs from a seedling to the Mature Age in 4 to 12 seconds', () => {
    expect(playDuration(40)).toBeCloseTo(7_800);
    expect(playDuration(2)).toBe(4_000);
    expect(playDuration(300)).toBe(12_000);
    expect(ageAt(0, 40)).toEqual({ age: PLAY_FROM, done: false });
    expect(ageAt(playDuration(40), 40)).toEqual({ age: 40, done: true });
    expect(ageAt(1e9, 40)).toEqual({ age: 40, done: true });
  });

  it('moves by tenths of a year, never back, so the tree grows without yearly jumps', () => {
    let last = 0;
    const steps = new Set<number>();
    for (let ms = 0; ms <= playDuration(40); ms += 16) {
      const { age } = ageAt(ms, 40);
      expect(age).toBeGreaterThanOrEqual(last);
      expect(Math.round(age * 10)).toBeCloseTo(age * 10, 6);
      steps.add(age);
      last = age;
    }
    // About one new Age per 0.2 s of a year / 10: hundreds of distinct steps, not forty.
    expect(steps.size).toBeGreaterThan(300);
  });
});
