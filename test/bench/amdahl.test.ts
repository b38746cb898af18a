import { expect, test } from 'vitest';
import { amdahlSpeedup, serialFraction } from '../../packages/bench/src/amdahl.js';

// The Karp-Flatt serial fraction is the inverse of Amdahl's law at the measured thread count: a
// speedup made by Amdahl's law from a fraction e gives e back (to rounding, 1e-12), and the projection
// from it reproduces the law at any core count.

test("serialFraction inverts Amdahl's law; the projection follows 1 / (e + (1 - e) / N)", () => {
  for (const e of [0, 0.05, 0.2, 0.5, 1]) {
    for (const p of [2, 4, 16]) {
      expect(serialFraction(amdahlSpeedup(e, p), p)).toBeCloseTo(e, 12);
    }
  }
  // Two threads, 1.7x: e = (1/1.7 - 1/2) / (1/2) = 0.17647...; on 8 cores 1 / (e + (1 - e) / 8) = 3.59...
  const e = serialFraction(1.7, 2);
  expect(e).toBeCloseTo(2 / 1.7 - 1, 12);
  expect(amdahlSpeedup(e, 8)).toBeCloseTo(1 / (e + (1 - e) / 8), 12);
  expect(amdahlSpeedup(e, 16)).toBeLessThan(1 / e);
  // Perfect scaling is no serial fraction; a superlinear one is clamped to 0; a slowdown past one thread to 1.
  expect(serialFraction(2, 2)).toBe(0);
  expect(serialFraction(2.5, 2)).toBe(0);
  expect(serialFraction(0.4, 2)).toBe(1);
  expect(serialFraction(1.5, 1)).toBeNaN();
  expect(serialFraction(NaN, 2)).toBeNaN();
});
