// The lantern show of fireworks (games/fireworks/lanterns.ts): the levels fit both sky shapes, a hot
// star lights only the lanterns it touches, stars against par, and real shells in the show's physics:
// one fired at a lantern lights it, one fired far from it does not, and a level-2 pair needs a held
// burst (a quick one between them lights neither).
import { describe, expect, it } from 'vitest';
import {
  BAND_MIDDLE,
  countShell,
  LEVELS,
  lanternAt,
  lanternRadius,
  lightFromSparks,
  sparkReach,
  starAt,
  starsFor,
  startLevel,
} from '../../games/fireworks/lanterns';
import { burstScale, createFireworks, launchShell, MAX_HOLD, stepFireworks } from '../../games/fireworks/show';

/** A phone's sky (the page gives a 390 x 844 phone about 64 x 108 m) and the desktop's. */
const phone = { width: 64, height: 108 };
const desktop = { width: 120, height: 80 };

/**
 * Fires one shell of level `level`'s kind towards (x, y), m, held `hold` s, in a fresh show of the
 * phone's sky, and runs 5 s (the burst at 2 s, its stars cold by 4.5 s) lighting lanterns as the page
 * does. @returns which lanterns are lit.
 */
function fire(level: number, x: number, y: number, hold: number): boolean[] {
  const { world, show } = createFireworks({ sky: phone, opening: 0, autoShow: false, generations: 1, seed: 5 });
  const run = startLevel(level, 0);
  expect(launchShell(world, show, x, y, hold, LEVELS[level]!.shell)).toBeGreaterThan(0);
  countShell(run);
  for (let i = 0; i < 300; i++) {
    stepFireworks(world, show);
    lightFromSparks(world, show, run);
  }
  return run.lit;
}

describe('lantern rules', () => {
  it('every lantern of every level stays in the sky and in the band (|y| <= 0.2 W), in both sky shapes', () => {
    for (const sky of [phone, desktop])
      for (const lv of LEVELS) {
        expect(lv.par).toBeLessThanOrEqual(lv.lanterns.length);
        for (const l of lv.lanterns) {
          expect(Math.abs(l.y)).toBeLessThanOrEqual(0.2);
          for (let t = 0; t < 24; t += 0.5) {
            const [x, y] = lanternAt(l, sky, t);
            const r = lanternRadius(sky.width);
            expect(x - r).toBeGreaterThan(0);
            expect(x + r).toBeLessThan(sky.width);
            // Where launchShell can aim: 12 m up to 3 m below the top.
            expect(y).toBeGreaterThan(12);
            expect(y).toBeLessThan(sky.height - 3);
          }
        }
      }
    expect(lanternAt({ x: 0.5, y: 0.1 }, phone, 0)).toEqual([32, BAND_MIDDLE * 108 + 6.4]);
    expect(lanternRadius(64)).toBe(3.4);
    expect(lanternRadius(120)).toBeCloseTo(3.84, 12);
  });
  it('a hot star lights the lanterns it touches (within a radius of the centre), not one just beyond', () => {
    const run = startLevel(0, 0);
    const [x, y] = lanternAt(LEVELS[0]!.lanterns[1]!, phone, 0);
    expect(starAt(run, phone, x + 3.45, y, 0)).toEqual([]);
    expect(starAt(run, phone, x + 3.35, y, 0)).toEqual([1]);
    expect(run.lit).toEqual([false, true, false]);
    expect(starAt(run, phone, x, y, 0)).toEqual([]); // already lit
  });
  it('the charging ring: a held burst reaches 1.57 times as far as a quick one; willows droop further than peonies', () => {
    const quick = sparkReach('peony', 1),
      held = sparkReach('peony', burstScale(MAX_HOLD));
    expect(held.side / quick.side).toBeCloseTo(Math.cbrt(3) ** 1.25, 9);
    expect(held.side / quick.side).toBeCloseTo(1.58, 2);
    expect(sparkReach('willow', 1).down).toBeGreaterThan(quick.down);
    expect(sparkReach('willow', 1).side).toBeLessThan(quick.side);
  });
  it('stars: 3 at par or better, 2 up to par + 2, then 1; shells after the level is lit are not counted', () => {
    expect([starsFor(2, 3), starsFor(3, 3), starsFor(4, 3), starsFor(5, 3), starsFor(6, 3)]).toEqual([3, 3, 2, 2, 1]);
    const run = startLevel(0, 0);
    for (let k = 0; k < 5; k++) countShell(run);
    for (const l of LEVELS[0]!.lanterns) starAt(run, phone, ...lanternAt(l, phone, 0), 0);
    expect(run.stars).toBe(2);
    countShell(run);
    expect(run.shells).toBe(5);
    expect(() => startLevel(LEVELS.length, 0)).toThrow(/startLevel: level/);
  });
});

describe('real shells in the show (64 m x 108 m phone sky, 300 stars a burst)', () => {
  it('level 1: a shell fired at a lantern lights it and no other; one fired 0.3 W above it lights nothing', () => {
    const [x, y] = lanternAt(LEVELS[0]!.lanterns[1]!, phone, 0);
    expect(fire(0, x, y, 0)).toEqual([false, true, false]);
    expect(fire(0, x, y + 0.3 * phone.width, 0)).toEqual([false, false, false]);
  });
  it('level 2: between the lower pair (0.4 W apart), a quick burst lights neither; one held 1.5 s lights both', () => {
    const lv = LEVELS[1]!;
    const [a, b] = [lanternAt(lv.lanterns[0]!, phone, 0), lanternAt(lv.lanterns[1]!, phone, 0)];
    const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2] as const;
    expect(fire(1, mid[0], mid[1], 0)).toEqual([false, false, false, false]);
    expect(fire(1, mid[0], mid[1], MAX_HOLD)).toEqual([true, true, false, false]);
  });
});
