/**
 * Black hole's predicted path is shorter on later levels (games/black-hole/levels.ts
 * `previewSeconds`, drawn by main.ts). The issue this answers: with 3 s of path on levels 1 to 4 a
 * stranger nudged until the dots turned blue and let go; levels lasted 5-6 s and the dots did the
 * thinking. Level 1 keeps the full 3 s (practice), as does any level after repeated falls on it (help);
 * otherwise the path shows the next 1 to 1.5 s only, so the route round the holes is planned by eye.
 */
import { describe, expect, test } from 'vitest';
import { FULL_PATH_SECONDS, PATH_HELP_FALLS, previewSeconds, startLevel } from '../../games/black-hole/levels';
import { createBlackHoleGame, createPredictor, predictPath } from '../../games/black-hole/rules';

describe('black hole: the predicted path shortens level by level', () => {
  test('the full 3 s on level 1 only, 1 to 1.5 s from level 2 (the stranger let 3 s of blue dots fly levels 1-4), 1 s from level 6', () => {
    expect(previewSeconds(1)).toBe(FULL_PATH_SECONDS);
    expect(FULL_PATH_SECONDS).toBe(3);
    for (let level = 2; level <= 30; level++) {
      expect(previewSeconds(level)).toBeLessThanOrEqual(previewSeconds(level - 1));
      expect(previewSeconds(level), `level ${level}`).toBeGreaterThanOrEqual(1);
      expect(previewSeconds(level), `level ${level}`).toBeLessThanOrEqual(1.5);
    }
    expect(previewSeconds(6)).toBe(1);
    expect(() => previewSeconds(0)).toThrow(/previewSeconds: level must be an integer >= 1/);
    expect(() => previewSeconds(2, -1)).toThrow(/previewSeconds: falls must be an integer >= 0/);
  });

  test('after PATH_HELP_FALLS falls on a level the full path comes back, as help', () => {
    for (let level = 2; level <= 12; level++) {
      for (let falls = 0; falls < PATH_HELP_FALLS; falls++) expect(previewSeconds(level, falls)).toBeLessThan(FULL_PATH_SECONDS);
      expect(previewSeconds(level, PATH_HELP_FALLS), `level ${level}`).toBe(FULL_PATH_SECONDS);
      expect(previewSeconds(level, PATH_HELP_FALLS + 4)).toBe(FULL_PATH_SECONDS);
    }
    expect(PATH_HELP_FALLS).toBeGreaterThanOrEqual(2);
  });

  test('from level 4 the path holding ↑ from the pad shows under half the climb to the line (it showed past the first hole)', () => {
    for (const field of [undefined, { width: 20, height: 30 }])
      for (let level = 4; level <= 8; level++) {
        const g = createBlackHoleGame({ seed: 1, ...(field ? { field } : {}) });
        startLevel(g, level);
        g.thrust = 'up';
        const steps = Math.round(previewSeconds(level) / g.world.dt);
        const out = new Float64Array(2 * (steps + 1));
        const n = predictPath(g, createPredictor(g), out, steps);
        let top = 0;
        for (let i = 0; i < n; i++) top = Math.max(top, out[2 * i + 1]!);
        expect(top - g.start[1], `level ${level}, ${g.field.width} m field`).toBeLessThan((g.lineY - g.start[1]) / 2);
        // The old 3 s path from the pad reached past half the climb (or into a hole on the way).
        const old = new Float64Array(2 * 181);
        const m = predictPath(g, createPredictor(g), old, 180);
        let oldTop = 0;
        for (let i = 0; i < m; i++) oldTop = Math.max(oldTop, old[2 * i + 1]!);
        expect(m < 181 || oldTop - g.start[1] > (g.lineY - g.start[1]) / 2, `level ${level}`).toBe(true);
      }
  });
});
