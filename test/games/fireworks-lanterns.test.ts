// The lantern show of fireworks (games/fireworks/lanterns.ts): the levels fit both sky shapes (a
// phone's tall sky plays tall layouts that fill its height), a hot star lights only the lanterns it
// touches, the tall layouts group the lanterns as their level means, the level shows as lit only once
// every glow is full, stars against par, and real shells in the show's physics: one fired at a
// lantern lights it, one fired far from it does not, and a level-2 pair needs a held burst (a quick
// one between them lights neither).
import { describe, expect, it } from 'vitest';
import {
  BAND_MIDDLE,
  bandMiddle,
  CLEAR_DELAY,
  clearShown,
  countShell,
  GLOW_RISE,
  glowOf,
  HOT_FRACTION,
  isTall,
  type Lantern,
  LEVELS,
  lanternAt,
  lanternRadius,
  lanternsOf,
  lightFromSparks,
  MEET_LIFT,
  MEET_WINDOW,
  meetCue,
  outOfShells,
  shellsLeft,
  shownLit,
  sparkReach,
  starAt,
  starsFor,
  startLevel,
  startWatch,
  TALL_BAND_MIDDLE,
  watchBursts,
} from '../../games/fireworks/lanterns';
import { burstScale, createFireworks, FUSE, launchShell, MAX_HOLD, stepFireworks } from '../../games/fireworks/show';

/** A phone's sky (the page gives a 390 x 844 phone about 64 x 108 m) and the desktop's. */

const phone = { width: 64, height: 108 };
const desktop = { width: 120, height: 80 };

/**
 * Fires one shell of level `level`'s kind towards (x, y), m, held `hold` s, in a fresh show of the
 * phone's sky (and one more towards each point of `more`), and runs 4 s (the burst at FUSE, 1.2 s,
 * its stars cold by 3.5 s) lighting lanterns and watching the bursts as the page does.
 * @returns which lanterns are lit, when each lit (world time, s), and the misses (bursts that lit nothing) with the world time each was known.
 */
function fireWatched(level: number, x: number, y: number, hold: number, ...more: [number, number][]) {
  const { world, show } = createFireworks({ sky: phone, opening: 0, autoShow: false, generations: 1, seed: 5 });
  const run = startLevel(level, 0);
  const watch = startWatch(show);
  for (const [px, py] of [[x, y], ...more]) {
    expect(launchShell(world, show, px!, py!, hold, LEVELS[level]!.shell)).toBeGreaterThan(0);
    countShell(run);
  }
  const misses: { x: number; y: number; time: number; until: number }[] = [];
  for (let i = 0; i < 240; i++) {
    stepFireworks(world, show);
    const lit = lightFromSparks(world, show, run);
    for (const m of watchBursts(watch, show, run, lit, world.time)) misses.push({ x: m.x, y: m.y, time: world.time, until: m.until });
  }
  return { lit: run.lit, litAt: run.litAt, misses, run };
}
/** Which lanterns `fireWatched` lights. */
function fire(level: number, x: number, y: number, hold: number, ...more: [number, number][]): boolean[] {
  return fireWatched(level, x, y, hold, ...more).lit;
}

describe('lantern rules', () => {
  it('every lantern of every level stays in the sky and in its band (wide |y| <= 0.2 W, tall |y| <= 0.5 W), in both sky shapes', () => {
    expect([isTall(phone), isTall(desktop)]).toEqual([true, false]);
    for (const sky of [phone, desktop])
      for (const [level, lv] of LEVELS.entries()) {
        expect(lv.par).toBeLessThanOrEqual(lv.lanterns.length);
        expect(lv.tall.length).toBe(lv.lanterns.length);
        for (const l of lanternsOf(level, sky)) {
          expect(Math.abs(l.y)).toBeLessThanOrEqual(isTall(sky) ? 0.5 : 0.2);
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
    expect(lanternAt({ x: 0.5, y: 0.1 }, phone, 0)).toEqual([32, TALL_BAND_MIDDLE * 108 + 6.4]);
    expect(lanternAt({ x: 0.5, y: 0.1 }, desktop, 0)).toEqual([60, BAND_MIDDLE * 80 + 12]);
    expect(bandMiddle(desktop)).toBe(BAND_MIDDLE);
    expect(lanternRadius(64)).toBe(3.4);
    expect(lanternRadius(120)).toBeCloseTo(3.84, 12);
  });
  it("a phone's tall layouts fill its height: each level's lanterns span 0.6 W or more of it (the wide ones 0.32 W at most)", () => {
    // The issue this answers: on a phone the lanterns and their bursts filled a band across the
    // middle of a sky 1.7 W tall, the rest of the screen empty.
    for (const [level, lv] of LEVELS.entries()) {
      const span = (ls: readonly Lantern[]) => Math.max(...ls.map((l) => l.y)) - Math.min(...ls.map((l) => l.y));
      expect(span(lanternsOf(level, phone)), lv.name).toBeGreaterThanOrEqual(0.6);
      expect(span(lanternsOf(level, desktop)), lv.name).toBeLessThanOrEqual(0.32 + 1e-9);
    }
  });
  it("the tall layouts keep each level's groups: the lanterns it means one burst to light together fit one held burst, no others do", () => {
    // Two (or three) lanterns can share a burst when some burst point has every one of them within
    // its hot stars' reach (sparkReach at the longest hold where the level allows holding, widened by
    // a lantern's radius), searched every 0.01 W; drifting lanterns every 0.25 s over 30 s.
    const W = phone.width,
      rho = lanternRadius(W) / W;
    const groups: number[][][] = [
      [
        [1, 2],
        [3, 4],
      ],
      [
        [0, 1],
        [2, 3],
      ],
      [[2, 3]],
      [
        [0, 1],
        [2, 3],
        [4, 5],
      ],
      [[1, 3, 4]],
    ];
    for (const [level, lv] of LEVELS.entries()) {
      const reach = sparkReach(lv.shell, lv.hold ? burstScale(MAX_HOLD) : 1);
      const fits = (pts: [number, number][]): boolean => {
        const xs = pts.map((p) => p[0]),
          ys = pts.map((p) => p[1]);
        // Burst points within reach of every lantern lie in this box (above the highest by at most
        // the reach down, below the lowest by at most the reach up).
        const sx = reach.side + rho;
        for (let px = Math.max(...xs) - sx; px <= Math.min(...xs) + sx; px += 0.01)
          for (let py = Math.max(...ys) - reach.up - rho; py <= Math.min(...ys) + reach.down + rho; py += 0.01)
            if (
              pts.every(([x, y]) => ((x - px) / (reach.side + rho)) ** 2 + ((y - py) / ((y > py ? reach.up : reach.down) + rho)) ** 2 <= 1)
            )
              return true;
        return false;
      };
      const ls = lanternsOf(level, phone);
      const at = (i: number, t: number): [number, number] => {
        const [x, y] = lanternAt(ls[i]!, phone, t);
        return [x / W, (y - bandMiddle(phone) * phone.height) / W];
      };
      const drifts = ls.some((l) => l.drift);
      const times = drifts ? Array.from({ length: 120 }, (_, k) => k * 0.25) : [0];
      const together = (set: number[]) => times.some((t) => fits(set.map((i) => at(i, t))));
      for (const g of groups[level]!) expect(together(g), `${lv.name}: ${g}`).toBe(true);
      const meant = (i: number, j: number) => groups[level]!.some((g) => g.includes(i) && g.includes(j));
      for (let i = 0; i < ls.length; i++)
        for (let j = i + 1; j < ls.length; j++) if (!meant(i, j)) expect(together([i, j]), `${lv.name}: ${i} with ${j}`).toBe(false);
    }
  });
  it('a level shows as lit CLEAR_DELAY after its last lantern lit, when every glow is full', () => {
    // The issue this answers: the "All lit" banner came up the moment the last lantern lit, before its
    // glow showed (the last burst still covered it).
    expect(GLOW_RISE).toBeLessThan(CLEAR_DELAY);
    const run = startLevel(0, 0);
    const ls = lanternsOf(0, phone);
    starAt(run, phone, ...lanternAt(ls[0]!, phone, 0), 1);
    starAt(run, phone, ...lanternAt(ls[1]!, phone, 0), 2);
    expect(glowOf(run, 1, 2 + GLOW_RISE / 2)).toBeCloseTo(0.5, 12);
    expect(glowOf(run, 2, 2)).toBe(0);
    starAt(run, phone, ...lanternAt(ls[2]!, phone, 0), 2.5);
    starAt(run, phone, ...lanternAt(ls[3]!, phone, 0), 2.8);
    starAt(run, phone, ...lanternAt(ls[4]!, phone, 0), 3);
    expect(run.stars).toBe(3);
    expect(clearShown(run, 3)).toBe(false);
    expect(clearShown(run, 3 + CLEAR_DELAY - 0.02)).toBe(false);
    expect(clearShown(run, 3 + CLEAR_DELAY)).toBe(true);
    for (let i = 0; i < 4; i++) expect(glowOf(run, i, 3 + CLEAR_DELAY)).toBe(1);
  });
  it('shells: each level gives par or more; the first one spare over par (a stray tap does not lose it); the first two fewer than lanterns (one a lantern runs out: each asks for its idea); spent with a lantern dark and nothing pending, the level is lost', () => {
    for (const lv of LEVELS) expect(lv.shells).toBeGreaterThanOrEqual(lv.par);
    expect(LEVELS[0]!.shells).toBe(LEVELS[0]!.par + 1);
    expect(LEVELS[0]!.par).toBeLessThan(LEVELS[0]!.lanterns.length);
    expect(LEVELS[0]!.shells).toBeLessThan(LEVELS[0]!.lanterns.length);
    expect(LEVELS[1]!.shells).toBeLessThan(LEVELS[1]!.lanterns.length);
    const run = startLevel(0, 0);
    expect(shellsLeft(run)).toBe(LEVELS[0]!.shells);
    for (let k = 0; k < LEVELS[0]!.shells; k++) countShell(run);
    expect(shellsLeft(run)).toBe(0);
    // Shells in flight or bursts still hot: not lost yet.
    expect(outOfShells(run, 1)).toBe(false);
    expect(outOfShells(run, 0)).toBe(true);
    // Every lantern lit with the last shell: won, not lost.
    const won = startLevel(0, 0);
    for (let k = 0; k < LEVELS[0]!.shells; k++) countShell(won);
    for (const l of lanternsOf(0, phone)) starAt(won, phone, ...lanternAt(l, phone, 0), 1);
    expect(outOfShells(won, 0)).toBe(false);
    expect(shellsLeft(won)).toBe(0);
    // Won with a shell to spare: the row still counts it (it read "Shells 0").
    const early = startLevel(0, 0);
    for (let k = 0; k < LEVELS[0]!.shells - 1; k++) countShell(early);
    for (const l of lanternsOf(0, phone)) starAt(early, phone, ...lanternAt(l, phone, 0), 1);
    expect(early.stars).toBeGreaterThan(0);
    expect(shellsLeft(early)).toBe(1);
    expect(() => outOfShells(run, -1)).toThrow(/outOfShells: pending/);
  });
  it('a hot star lights the lanterns it touches (within a radius of the centre), not one just beyond', () => {
    const run = startLevel(0, 0);
    const [x, y] = lanternAt(lanternsOf(0, phone)[1]!, phone, 0);
    expect(starAt(run, phone, x + 3.45, y, 0)).toEqual([]);
    expect(starAt(run, phone, x + 3.35, y, 0)).toEqual([1]);
    expect(run.lit).toEqual([false, true, false, false, false]);
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
  it("the finale's meeting cue: a press a hold and a fuse before the low pair is closest, the release a fuse before, aimed at the three; none on other levels or once the pair is lit", () => {
    const finale = LEVELS.findIndex((l) => l.meet);
    expect(finale).toBe(LEVELS.length - 1);
    for (const sky of [phone, desktop]) {
      const none = lanternsOf(finale, sky).map(() => false);
      for (let level = 0; level < finale; level++) expect(meetCue(level, sky, 0.3, none)).toBeNull();
      // The pair swings with period 6 s and is closest (0.2 W apart) at 1.5 s: over a swing (from
      // -2 s, so neither window wraps), where a release now (or a press now, held MAX_HOLD) bursts
      // within half MEET_WINDOW of that, 0.05 s apart.
      const release: number[] = [],
        press: number[] = [];
      for (let t = -2; t < 4 - 1e-9; t += 0.05) {
        const cue = meetCue(finale, sky, t, none);
        if (cue && cue.release >= 0.5) release.push(t);
        if (cue && cue.press >= 0.5) press.push(t);
      }
      const mid = (ts: number[]) => (ts[0]! + ts.at(-1)!) / 2;
      expect(mid(release)).toBeCloseTo(1.5 - FUSE, 1);
      expect(mid(press)).toBeCloseTo(1.5 - FUSE - MAX_HOLD, 1);
      // Gap within 0.035 W of 0.2 W: 0.2 sin(2 pi t / 6) >= 0.165, about 1.2 s of the 6.
      expect(release.length * 0.05).toBeGreaterThan(1);
      expect(release.length * 0.05).toBeLessThan(1.4);
      expect(MEET_WINDOW).toBeLessThan(0.1);
      // Aimed MEET_LIFT over the mean of the middle lantern and the pair, on the middle line.
      const cue = meetCue(finale, sky, 1.5 - FUSE, none)!;
      const [, my] = lanternAt(lanternsOf(finale, sky)[1]!, sky, 1.5);
      const [, py] = lanternAt(lanternsOf(finale, sky)[3]!, sky, 1.5);
      expect(cue.x).toBeCloseTo(0.5 * sky.width, 6);
      expect(cue.y).toBeCloseTo((my + 2 * py) / 3 + MEET_LIFT * sky.width, 6);
      expect(meetCue(finale, sky, 1.5 - FUSE, [false, false, false, true, false])).toBeNull();
    }
  });
  it('stars: 3 at par or better, 2 up to par + 2, then 1; shells after the level is lit are not counted', () => {
    expect([starsFor(2, 3), starsFor(3, 3), starsFor(4, 3), starsFor(5, 3), starsFor(6, 3)]).toEqual([3, 3, 2, 2, 1]);
    const run = startLevel(0, 0);
    for (let k = 0; k < 5; k++) countShell(run);
    for (const l of lanternsOf(0, phone)) starAt(run, phone, ...lanternAt(l, phone, 0), 0);
    expect(run.stars).toBe(2);
    countShell(run);
    expect(run.shells).toBe(5);
    expect(() => startLevel(LEVELS.length, 0)).toThrow(/startLevel: level/);
  });
});

describe('real shells in the show (64 m x 108 m phone sky, 300 stars a burst)', () => {
  it('level 1: a shell fired at a lone lantern lights it and no other; one 0.3 W above it lights nothing and is a miss once its stars are cold; one right between the close pair lights both; the row counts a lantern once its glow is full', () => {
    const ls = lanternsOf(0, phone);
    const [x, y] = lanternAt(ls[0]!, phone, 0);
    const [a, b] = [lanternAt(ls[1]!, phone, 0), lanternAt(ls[2]!, phone, 0)];
    const [fx, fy] = lanternAt(ls[3]!, phone, 0);
    // Three shells in one show, far enough apart not to reach each other's lanterns: lantern 0 lit,
    // the pair lit by the one between them, lantern 3 (the shell 0.3 W above it) not, nor its pair 4.
    const r = fireWatched(0, x, y, 0, [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2], [fx, fy + 0.3 * phone.width]);
    expect(r.lit).toEqual([true, true, true, false, false]);
    // One miss, the shell over lantern 3 (it bursts on its target), said once its hot stars (40 % of
    // a peony star's longest life, 2.2 s) are cold: the step after FUSE + 0.88 s.
    expect(r.misses.length).toBe(1);
    const m = r.misses[0]!;
    expect(Math.hypot(m.x - fx, m.y - (fy + 0.3 * phone.width))).toBeLessThan(0.1);
    expect(m.until).toBeCloseTo(FUSE + HOT_FRACTION * 2.2, 1);
    expect(m.time).toBeGreaterThan(m.until);
    expect(m.time).toBeLessThan(m.until + 1.5 / 60);
    // "Lit n/5" counts a lantern from the moment it lights (with its glow and the "Double!"), not before.
    const first = Math.min(...r.litAt.filter((t) => !Number.isNaN(t)));
    expect(shownLit(r.run, first - 0.01)).toBe(0);
    expect(shownLit(r.run, first)).toBeGreaterThanOrEqual(1);
    expect(glowOf(r.run, r.litAt.indexOf(first), first + GLOW_RISE / 2)).toBeLessThan(1);
    expect(shownLit(r.run, 100)).toBe(3);
  });
  it("level 3: shells at the lone lanterns' ghosts and one where the passing pair's ghosts meet light all four in par 3; the same shell while the pair is apart lights neither", () => {
    // The pair swings towards each other with period 5 s, closest (0.08 W apart, one over the other)
    // at 1.25 s and 6.25 s, farthest (0.76 W apart) at 3.75 s: a shell launched at 0 bursts as they
    // meet, one launched at 2.5 s bursts with them farthest apart.
    const ls = lanternsOf(2, phone);
    const ghosts = ls.map((l) => lanternAt(l, phone, FUSE));
    const meet: [number, number] = [(ghosts[2]![0] + ghosts[3]![0]) / 2, (ghosts[2]![1] + ghosts[3]![1]) / 2];
    expect(Math.hypot(ghosts[2]![0] - ghosts[3]![0], ghosts[2]![1] - ghosts[3]![1]) / phone.width).toBeLessThan(0.1);
    expect(fire(2, ...ghosts[0]!, 0, ghosts[1]!, meet)).toEqual([true, true, true, true]);
    const { world, show } = createFireworks({ sky: phone, opening: 0, autoShow: false, generations: 1, seed: 5 });
    const run = startLevel(2, 0);
    while (world.time < 2.5) stepFireworks(world, show);
    const apart = ls.slice(2).map((l) => lanternAt(l, phone, world.time + FUSE));
    expect(Math.abs(apart[0]![0] - apart[1]![0]) / phone.width).toBeGreaterThan(0.7);
    expect(launchShell(world, show, ...meet, 0, 'peony')).toBeGreaterThan(0);
    for (let i = 0; i < 240; i++) {
      stepFireworks(world, show);
      lightFromSparks(world, show, run);
    }
    expect(run.lit).toEqual([false, false, false, false]);
  });
  it('level 5: a shell held on the meeting cue and let go when it says so (from the start, 0.3 s before its middle) lights the pair and the lantern above', () => {
    const finale = LEVELS.length - 1;
    const cue = meetCue(finale, phone, 0, [false, false, false, false, false])!;
    expect(cue.release).toBeGreaterThanOrEqual(0.5);
    expect(fire(finale, cue.x, cue.y, MAX_HOLD)).toEqual([false, true, false, true, true]);
  });
  it('level 4: a quick willow on a top lantern lights only it (its column is 0.3 W tall); one held 1.5 s a little above it lights the column', () => {
    const ls = lanternsOf(3, phone);
    const [tx, ty] = lanternAt(ls[0]!, phone, 0);
    const [, by] = lanternAt(ls[1]!, phone, 0);
    expect((ty - by) / phone.width).toBeCloseTo(0.3, 9);
    expect(fire(3, tx, ty, 0)).toEqual([true, false, false, false, false, false]);
    expect(fire(3, tx, ty - 0.03 * phone.width, MAX_HOLD)).toEqual([true, true, false, false, false, false]);
  });
  it('level 2: between the lower pair (0.4 W apart), a quick burst lights neither; one held 1.5 s lights both', () => {
    const ls = lanternsOf(1, phone);
    const [a, b] = [lanternAt(ls[0]!, phone, 0), lanternAt(ls[1]!, phone, 0)];
    const mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2] as const;
    expect(fire(1, mid[0], mid[1], 0)).toEqual([false, false, false, false]);
    expect(fire(1, mid[0], mid[1], MAX_HOLD)).toEqual([true, true, false, false]);
  });
});
