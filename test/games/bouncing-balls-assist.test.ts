// The phone's pull assist of bouncing balls (games/bouncing-balls/hoop.ts assistPull): over a grid of
// touch pulls from a standard start into the warm-up hoop of the tall box (a phone held upright), the
// px of pull length that throw a clean basket (reach.ts cleanBasket: the throw's drag-free flight in
// the scene's default physics goes down through the opening before it touches anything), without and
// with the assist. Independent of the assist: the baskets are judged by the flight itself.
import { describe, expect, it } from 'vitest';
import { assistPull, HOOP_SPOTS_TALL, PULL_ASSIST_PX, slingSpeed } from '../../games/bouncing-balls/hoop';
import { cleanBasket, findBasket } from '../../games/bouncing-balls/reach';

/** The phone's full pull, px (main.ts fullPull at 390 x 844: 60 % of the canvas' width, at least 230). */
const FULL = 234;

describe('bouncing-balls pull assist', () => {
  it('widens the pull lengths that score from the standard start at least 3 times', () => {
    const spot = HOOP_SPOTS_TALL[0]!;
    // The standard start: the lowest-left natural start with a robust basket into the warm-up hoop.
    const basket = findBasket(spot, true, 3, 3);
    expect(basket).not.toBeNull();
    const { x, y, angle } = basket!;
    const STEP = 0.5;
    let before = 0,
      after = 0;
    // Pull directions 1 degree apart, 3 either side of the basket's; lengths every 0.5 px up to the full pull.
    for (let da = -3; da <= 3; da++) {
      const scores = (length: number) =>
        length <= FULL && cleanBasket(spot, true, { x, y, angle: angle + da, speed: slingSpeed(length, FULL) });
      for (let length = STEP; length <= FULL; length += STEP) {
        if (scores(length)) before += STEP;
        if (scores(assistPull(length, scores))) after += STEP;
      }
    }
    before /= 7;
    after /= 7;
    // A few px wide without it (a thumb's jitter), some 2 PULL_ASSIST_PX wider with it.
    expect(before).toBeGreaterThan(3);
    expect(before).toBeLessThan(20);
    expect(after).toBeGreaterThanOrEqual(3 * before);
    expect(after).toBeLessThanOrEqual(before + 2 * PULL_ASSIST_PX + 4 * STEP + 1e-9);
  }, 60_000);

  it('leaves a pull alone when no length within its reach scores, and snaps to the middle of a run', () => {
    const run = (l: number) => l >= 50 && l <= 60;
    expect(assistPull(30, run, 10)).toBe(30);
    expect(assistPull(42, run, 10)).toBe(55);
    expect(assistPull(53, run, 10)).toBe(55);
    expect(assistPull(70, run, 10)).toBe(55);
    expect(assistPull(71, run, 10)).toBe(71);
    // A run longer than 2 reach either way of the hit is followed that far only.
    expect(assistPull(0, (l) => l >= 0, 5)).toBe(5);
  });

  it('rejects bad input, naming the parameter', () => {
    expect(() => assistPull(-1, () => true)).toThrow(/assistPull: length/);
    expect(() => assistPull(Number.NaN, () => true)).toThrow(/assistPull: length/);
    expect(() => assistPull(10, () => true, -1)).toThrow(/assistPull: reach/);
    expect(() => assistPull(10, () => true, 5, 0)).toThrow(/assistPull: step/);
  });
});
