/**
 * seededRandom: the same seed gives the same numbers, every number lies in [0, 1), and the numbers are
 * spread evenly (a chi-square test against the uniform distribution).
 */
import { describe, expect, it } from 'vitest';
import { seededRandom } from '../../packages/game-kit/src/random';

describe('seededRandom', () => {
  it('repeats a sequence for a seed, and another seed gives another', () => {
    const a = seededRandom(42),
      b = seededRandom(42),
      c = seededRandom(43);
    const sa = Array.from({ length: 50 }, a),
      sb = Array.from({ length: 50 }, b),
      sc = Array.from({ length: 50 }, c);
    expect(sa).toEqual(sb);
    expect(sa.filter((x, i) => x === sc[i]).length).toBe(0);
    // Seed 0 is not a degenerate start: its numbers differ from one another.
    const z = seededRandom(0);
    expect(new Set(Array.from({ length: 50 }, z)).size).toBe(50);
  });

  it('gives numbers in [0, 1) spread evenly over 20 bins', () => {
    const n = 100_000,
      bins = new Array<number>(20).fill(0),
      r = seededRandom(7);
    let outside = 0;
    for (let i = 0; i < n; i++) {
      const x = r();
      if (!(x >= 0 && x < 1)) outside++;
      else bins[Math.floor(x * 20)]!++;
    }
    expect(outside).toBe(0);
    const e = n / 20;
    const chi2 = bins.reduce((s, k) => s + ((k - e) * (k - e)) / e, 0);
    // 19 degrees of freedom: chi-square exceeds 43.8 with probability 0.001 for uniform numbers; a
    // generator stuck in a short cycle or biased by 1 % in a bin (chi2 about 100) fails.
    expect(chi2).toBeLessThan(43.8);
  });

  it('refuses a seed that is not a finite number, naming itself', () => {
    expect(() => seededRandom(Number.NaN)).toThrow(/seededRandom: seed must be a finite number, got NaN/);
    expect(() => seededRandom(Number.POSITIVE_INFINITY)).toThrow(RangeError);
  });
});
