/**
 * Black hole's late levels ask for steering even with the predicted path shown. The issue this
 * answers: strangers cleared levels 7 and 8 with one hold of ↑ of 1.5 to 2 s, waiting at the pad for
 * the drifting holes to clear the way (the path from the pad turned blue), then letting the ship coast
 * up. Measured before the fix (seeds 1-4, ↑ pressed 0 to 6 s after the level began, held 0.5 to 3 s):
 * 27 %, 45 % and 41 % of those flights cleared levels 6, 7 and 8 on the desktop's 32 x 24 m field,
 * 30 %, 49 % and 58 % on the phone's 20 x 30 m one. Now the first hole across the straight path stays
 * put (games/black-hole/levels.ts `LevelSpec.anchored`), so no single hold clears them, while a player
 * who steers round the holes (test/games/black-hole-players.ts, flying by eye) still does.
 */
import { describe, expect, test } from 'vitest';
import { levelSpec } from '../../games/black-hole/levels';
import { FIELD } from '../../games/black-hole/rules';
import { PLAYERS, playLevel, singleHold, singleHolds } from './black-hole-players';

/** The fields the page makes at 1280 x 800 (the default 32 x 24 m) and at 390 x 844 (20 x 30 m). */
const FIELDS = [FIELD, { width: 20, height: 30 }] as const;
/** Hold lengths, s: 0.5 to 3 in steps of 0.1. */
const HOLDS = Array.from({ length: 26 }, (_, i) => 0.5 + 0.1 * i);
/** Waits before the press, s: at once, and while the holes drift for up to 6 s. */
const WAITS = [0, 2, 4, 6];

describe('black hole: one hold of ↑ does not clear a late level', () => {
  test("levels 3 to 8: no hold of ↑ of 0.5 to 3 s, pressed at once or after a wait of up to 6 s, then let go, clears them (the page's seed, both fields)", () => {
    // Seed 1 only (the page's unless ?seed asks for another): each flight steps a whole game, exhaust
    // and all. Seeds 1-4 with waits 0 to 6 s by 1 s: none of 4368 flights cleared. The holds of one
    // wait are flown longest first (`singleHolds`): a hold still held where a longer hold's flight
    // fell ends the same way at the same step, so about a quarter of the flights are not flown again.
    const cleared: string[] = [];
    let flights = 0;
    for (const field of FIELDS)
      for (const level of [3, 4, 5, 6, 7, 8])
        for (const seed of [1])
          for (const wait of WAITS)
            singleHolds(level, seed, HOLDS, field, wait).forEach((end, i) => {
              flights++;
              if (end === 'cleared')
                cleared.push(`${field.width} m, level ${level}, seed ${seed}: wait ${wait} s, hold ${HOLDS[i]!.toFixed(1)} s`);
            });
    expect(flights).toBe(2 * 6 * WAITS.length * HOLDS.length);
    expect(cleared).toEqual([]);
  }, 300_000);

  test('the check can fail: after a wait longer than any the layout check flies, a hold clears level 8; held ↑ on level 6 falls in', () => {
    // The measure itself says 'cleared' where a hold gets through: on level 8 (seed 1, the desktop's
    // field) the holes drift for 10 s and then holds of 0.5 to 0.8 s get through (the layout check
    // waits at most 6 s; level 8 has no ring). Level 3's zig-zag, which let 7 of the 26 through, is now checked too.
    expect(levelSpec(5).anchored).toBe(false);
    expect([6, 7, 8].map((l) => levelSpec(l).anchored)).toEqual([true, true, true]);
    const ends = singleHolds(8, 1, HOLDS, FIELD, 10, 20, false);
    expect(ends.filter((end) => end === 'cleared').length).toBeGreaterThan(0);
    // The shortcut of the sweep above (`singleHolds`: a hold still held where a longer one's flight
    // ended is not flown again) gives what each flight flown alone gives, clears included.
    expect(ends).toEqual(HOLDS.map((hold) => singleHold(8, 1, hold, FIELD, 10, 20, false)));
    // Level 7's ring stops such holds: after the same wait none clears it.
    expect(HOLDS.filter((hold) => singleHold(7, 1, hold, FIELD, 10) === 'cleared')).toEqual([]);
    expect(HOLDS.filter((hold) => singleHold(3, 1, hold, FIELD) === 'cleared')).toEqual([]);
    expect(singleHold(6, 1, 3, FIELD)).toBe('fell');
  }, 60_000);

  test('levels 6 to 8 stay winnable: a player who steers by eye (the sharp one) clears each on seeds 1 and 2 of both fields within 60 s', () => {
    for (const field of FIELDS)
      for (const level of [6, 7, 8])
        for (const seed of [1, 2]) {
          const o = playLevel(level, seed, PLAYERS.sharp, 60, field);
          expect(o.cleared, `${field.width} m, level ${level}, seed ${seed}`).toBe(true);
        }
  }, 120_000);
});
