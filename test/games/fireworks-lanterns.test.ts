// The lantern show of fireworks (games/fireworks/lanterns.ts): burst reach against the show's own
// formula, the levels' pairs needing a held burst, stars against par, and a real shell in the show's
// physics that bursts at its target and lights the lantern it was aimed at.
import { describe, expect, it } from 'vitest';
import { burstAt, burstReach, countShell, LEVELS, lanternAt, lanternRadius, starsFor, startLevel } from '../../games/fireworks/lanterns';
import { BURST_REFERENCE_WIDTH, burstScale, createFireworks, launchShell, MAX_HOLD, stepFireworks } from '../../games/fireworks/show';

const sky = { width: 64, height: 140 };

describe('lantern rules', () => {
  it('a quick burst reaches 0.175 sky widths (11.2 m in a 64 m sky), the longest hold 1.44 times that', () => {
    expect(burstReach(1, 1)).toBeCloseTo(0.7 * 16, 12);
    expect(burstReach(1, burstScale(MAX_HOLD)) / burstReach(1, 1)).toBeCloseTo(Math.cbrt(3), 6);
  });
  it('level 2: a quick burst between the pair lights neither; a held one lights both', () => {
    const lv = LEVELS[1]!;
    const [a, b] = [lanternAt(lv.lanterns[0]!, sky, 0), lanternAt(lv.lanterns[1]!, sky, 0)];
    const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2] as const;
    const quick = startLevel(1, 0);
    expect(burstAt(quick, sky, sky.width / BURST_REFERENCE_WIDTH, mid[0], mid[1], 1, 0)).toBe(0);
    const held = startLevel(1, 0);
    expect(burstAt(held, sky, sky.width / BURST_REFERENCE_WIDTH, mid[0], mid[1], burstScale(MAX_HOLD), 0)).toBe(2);
    expect(held.lit).toEqual([true, true, false]);
  });
  it('level 4: two held bursts at the 2nd and 4th lanterns light all five (par 2) for 3 stars', () => {
    const run = startLevel(3, 0);
    const reach = sky.width / BURST_REFERENCE_WIDTH;
    for (const i of [1, 3]) {
      countShell(run);
      const [x, y] = lanternAt(LEVELS[3]!.lanterns[i]!, sky, 0);
      burstAt(run, sky, reach, x, y, burstScale(MAX_HOLD), 1);
    }
    expect(run.lit).toEqual([true, true, true, true, true]);
    expect(run.stars).toBe(3);
  });
  it('a drifting lantern moves: level 3 lantern 1 is 0.14 W to the side a quarter period in', () => {
    const l = LEVELS[2]!.lanterns[0]!;
    expect(lanternAt(l, sky, l.period! / 4)[0] - lanternAt(l, sky, 0)[0]).toBeCloseTo(0.14 * sky.width, 9);
  });
  it('stars: 3 at par or better, 2 up to par + 2, then 1; shells after the level is lit are not counted', () => {
    expect([starsFor(2, 3), starsFor(3, 3), starsFor(4, 3), starsFor(5, 3), starsFor(6, 3)]).toEqual([3, 3, 2, 2, 1]);
    const run = startLevel(0, 0);
    for (let k = 0; k < 5; k++) countShell(run);
    for (const l of LEVELS[0]!.lanterns) burstAt(run, sky, 1, ...lanternAt(l, sky, 0), 1, 0);
    expect(run.stars).toBe(2);
    countShell(run);
    expect(run.shells).toBe(5);
  });
  it('every lantern of every level lies in the sky (both shapes), and startLevel rejects a bad level', () => {
    for (const s of [sky, { width: 120, height: 70 }])
      for (const lv of LEVELS)
        for (const l of lv.lanterns)
          for (const t of [0, 1.5, 3, 4.5]) {
            const [x, y] = lanternAt(l, s, t);
            expect(x - lanternRadius(s.width)).toBeGreaterThan(0);
            expect(x + lanternRadius(s.width)).toBeLessThan(s.width);
            expect(y).toBeGreaterThan(12);
            expect(y).toBeLessThan(s.height - 3);
          }
    expect(() => startLevel(LEVELS.length, 0)).toThrow(/startLevel: level/);
  });
});

describe('a shell in the show lights the lantern it was aimed at', () => {
  it('64 m x 140 m sky: a quick shell at level 1 lantern 2 bursts within reach of it, not of the others', () => {
    const { world, show } = createFireworks({ sky, opening: 0, autoShow: false, sparks: 20, generations: 1 });
    const run = startLevel(0, 0);
    const [tx, ty] = lanternAt(LEVELS[0]!.lanterns[1]!, sky, 0);
    const id = launchShell(world, show, tx, ty, 0, 'peony');
    expect(id).toBeGreaterThan(0);
    const before = show.flashCount;
    for (let i = 0; i < 200 && show.flashCount === before; i++) stepFireworks(world, show);
    expect(show.flashCount).toBe(before + 1);
    const f = 4 * (before % 16);
    const [bx, by] = [show.flashes[f]!, show.flashes[f + 1]!];
    // The shell bursts near its target (its flight is timed to the fuse): within 2 m.
    expect(Math.hypot(bx - tx, by - ty)).toBeLessThan(2);
    expect(burstAt(run, sky, show.reach, bx, by, show.flashes[f + 3]!, world.time)).toBe(1);
    expect(run.lit).toEqual([false, true, false]);
  });
});
