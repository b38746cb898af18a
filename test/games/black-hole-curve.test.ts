/**
 * Black hole's difficulty curve as scripted players meet it (test/games/black-hole-players.ts: they fly
 * by eye along a way round the holes with a bounded reaction). The issue this answers: levels 1 to 3
 * were cleared in seconds, then level 5 ended the game. Measured in full with
 * `node scripts/black-hole-curve.mjs` (seeds 1-8, both fields); here seeds 1-4 on the desktop's field,
 * to stay cheap, so the tolerances allow a seed's extra try or two.
 */
import { describe, expect, test } from 'vitest';
import { levelFigures, PLAYERS, playLevel } from './black-hole-players';

/** Each figure's level, tries a seed, success and clearing try's time (s), for the failure messages. */
const show = (fs: readonly ReturnType<typeof levelFigures>[]): string =>
  JSON.stringify(fs.map((f) => [f.level, f.tries, f.success.toFixed(2), f.time.toFixed(1)]));

describe('black hole difficulty curve', () => {
  test('the middle player clears levels 1 to 5 on every seed: level 1 at the first try but not in a dash, the later ones asking more, none a cliff', () => {
    const figures = [1, 2, 3, 4, 5].map((level) => levelFigures(level, PLAYERS.middle, 4, 60));
    const where = show(figures);
    for (const f of figures) expect(f.cleared, `level ${f.level}: ${where}`).toBe(4);
    // Holding up reaches the line in about 2.7 s; level 1's one hole makes the player steer for more than 4 s.
    expect(figures[0]!.success, where).toBe(1);
    expect(figures[0]!.time, where).toBeGreaterThan(4);
    // The levels after practice ask more of it: on some seed of levels 4 and 5 it takes a second try.
    // (Levels 2 and 3 may go at the first try: they are the first steps after practice, kept gentle.)
    expect(Math.min(figures[3]!.success, figures[4]!.success), where).toBeLessThan(1);
    // No cliff: a try clears at least 2 times in 5 (level 5 once took 24 tries on a seed).
    for (const f of figures.slice(1)) expect(f.success, `level ${f.level}: ${where}`).toBeGreaterThanOrEqual(0.4);
  });

  test("the step from practice to level 2's wall is no cliff: on the phone's field a slow player's try clears it at least 1 time in 2", () => {
    // A stranger's first run ended on level 2. On the 20 x 30 m field the slow player's success there
    // was 0.07 (seeds 1-12; 5 to 7 tries a seed, falling into the holes at the wall's gap edge) after
    // level 1's 0.96; now 0.68. Seeds 1-4 to stay cheap: 0.5 allows a seed's extra try or two.
    const f = levelFigures(2, PLAYERS.slow, 4, 60, { width: 20, height: 30 });
    expect(f.success, show([f])).toBeGreaterThanOrEqual(0.5);
  });

  test('the slow player meets no cliff from level 2 to 4: the chance a try clears falls by under 0.3 a level', () => {
    // The zig-zag of level 3 with 0.4 to 0.5 m horizons: success 0.68, 0.17, 0.50 on levels 2, 3, 4.
    const figures = [2, 3, 4].map((level) => levelFigures(level, PLAYERS.slow, 4, 60));
    for (let i = 1; i < figures.length; i++)
      expect(figures[i - 1]!.success - figures[i]!.success, `level ${figures[i]!.level}: ${show(figures)}`).toBeLessThan(0.3);
  });

  test('levels 4 and 5 are no cliff for the slow player: a try clears at least 2 times in 5 where each was steepest', () => {
    // Level 4's holes of 0.5 to 0.7 m and level 5's of 0.45 to 0.85 m (seeds 1-12): the slow player's
    // success 0.58 on level 3 fell to 0.29 on level 4 on the phone's field, and to 0.23 / 0.25 on level 5
    // (desktop / phone); now 0.56 / 0.52 on level 4 and 0.53 / 0.60 on level 5. Seeds 1-4 to stay cheap,
    // on the field where each level was steepest: before 0.17 (level 4, phone) and 0.05 (level 5,
    // desktop), now 0.55 and 0.48. The runs are seeded, so 0.4 (the aim over 12 seeds) is no flake.
    const figures = [levelFigures(4, PLAYERS.slow, 4, 60, { width: 20, height: 30 }), levelFigures(5, PLAYERS.slow, 4, 60)];
    for (const f of figures) expect(f.success, `level ${f.level}: ${show(figures)}`).toBeGreaterThanOrEqual(0.4);
  });

  test("level 6, where the holes start to drift, is no cliff after level 5: on the phone's field the middle player's success falls by under 0.2", () => {
    // Level 6 drifted four bigger holes (0.55 to 1 m): success 0.42 on these seeds (0.44 over 12) after
    // level 5's 1.0 (0.85 over 12). Now three of level 5's smaller holes drift: 0.88 (0.89 over 12). Seeds 1-4 on
    // the 20 x 30 m field to stay cheap; 0.2 is about the step between earlier levels over 12 seeds.
    const figures = [5, 6].map((level) => levelFigures(level, PLAYERS.middle, 4, 60, { width: 20, height: 30 }));
    expect(figures[0]!.success - figures[1]!.success, show(figures)).toBeLessThan(0.2);
  });

  test('a player who reacts later falls more: the slow player takes more tries than the sharp one on level 4', () => {
    // The players' skill shows in the measure (else the curves above could not tell levels apart).
    const tries = (style: (typeof PLAYERS)[keyof typeof PLAYERS]): number =>
      [1, 2, 3, 4].reduce((n, seed) => n + playLevel(4, seed, style, 30).tries, 0);
    expect(tries(PLAYERS.slow)).toBeGreaterThan(tries(PLAYERS.sharp));
    expect(() => playLevel(1, 1, { ...PLAYERS.middle, react: 0 })).toThrow(/playLevel: limit, react and speed must be > 0/);
  });
});
