/**
 * Black hole's levels from 4 on each draw their holes from a stream of their own
 * (games/black-hole/levels.ts `levelSeed`). The issue this answers: every level's draws started from
 * the same point of the game's generator, so levels of the same kind (6 and 8, and 7 and 8 on seed 1)
 * opened with their holes in the same places, only their sizes differing: the mean distance from a
 * hole of one to the nearest hole of the other was 0.00 to 0.04 m. Their layouts keep to a plan (holes
 * across the straight path, on the diagonals), so two different draws still lie 0.5 m or so apart.
 */
import { slotOf } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { levelSeed, startLevel } from '../../games/black-hole/levels';
import { type BlackHoleGame, createBlackHoleGame, FIELD, type FieldSize } from '../../games/black-hole/rules';

/** Level `level`'s hole centres, m, in a new game of `seed` on `field`. */
function centres(level: number, seed: number, field: FieldSize = FIELD): [number, number][] {
  const g: BlackHoleGame = createBlackHoleGame({ seed, field, lives: 9 });
  startLevel(g, level);
  const P = g.world.components.Position;
  return g.holes.map((h) => [P.x[slotOf(h)]!, P.y[slotOf(h)]!]);
}

/** Mean over the holes of `a` of the distance to the nearest hole of `b`, m. */
function apart(a: readonly [number, number][], b: readonly [number, number][]): number {
  let sum = 0;
  for (const [x, y] of a) sum += Math.min(...b.map(([u, v]) => Math.hypot(x - u, y - v)));
  return sum / a.length;
}

describe('black hole: each level its own layout', () => {
  test('levels 4 to 8 open with different layouts: a hole of one lies 0.25 m or more from the nearest of another, on average (the same layout: under 0.05 m) (seeds 1-4, both fields)', () => {
    const close: string[] = [];
    let least = Infinity;
    for (const field of [FIELD, { width: 20, height: 30 }])
      for (const seed of [1, 2, 3, 4]) {
        const ls = [4, 5, 6, 7, 8].map((level) => centres(level, seed, field));
        for (let i = 0; i < ls.length; i++)
          for (let j = i + 1; j < ls.length; j++) {
            const d = apart(ls[i]!, ls[j]!);
            least = Math.min(least, d);
            if (d < 0.25) close.push(`${field.width} m seed ${seed}: levels ${i + 4} and ${j + 4}, ${d.toFixed(2)} m`);
          }
      }
    expect(close, `least ${least.toFixed(2)} m`).toEqual([]);
  });

  test('levelSeed: one 32-bit seed per game seed and level, all different; bad input throws', () => {
    const seen = new Set<number>();
    for (let seed = 0; seed < 50; seed++)
      for (let level = 1; level <= 40; level++) {
        const s = levelSeed(seed, level);
        expect(Number.isInteger(s) && s >= 0 && s < 2 ** 32).toBe(true);
        seen.add(s);
      }
    expect(seen.size).toBe(50 * 40);
    expect(levelSeed(7, 5)).toBe(levelSeed(7, 5));
    expect(() => levelSeed(1, 0)).toThrow(/levelSeed: level must be an integer >= 1, got 0/);
    expect(() => levelSeed(Number.NaN, 2)).toThrow(/levelSeed: seed must be finite/);
  });
});
