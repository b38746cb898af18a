/**
 * Black hole's predicted path is shorter on later levels (games/black-hole/levels.ts
 * `previewSeconds`, drawn by main.ts). The issue this answers: with 3 s of path on every level a
 * stranger followed the dots up and levels lasted some 5 s; the dots did the thinking. Levels 1 and 2
 * keep 3 s (practice, and the wall, whose pull is learnt from the path), later levels show the next
 * moment only, so the route round the holes has to be planned by eye.
 */
import { describe, expect, test } from 'vitest';
import { previewSeconds, startLevel } from '../../games/black-hole/levels';
import { createBlackHoleGame, createPredictor, predictPath } from '../../games/black-hole/rules';

describe('black hole: the predicted path shortens level by level', () => {
  test('3 s on levels 1 and 2, never longer a level later, 1.5 s or less from level 4, 1 s from level 6', () => {
    expect([1, 2].map(previewSeconds)).toEqual([3, 3]);
    for (let level = 2; level <= 30; level++) expect(previewSeconds(level)).toBeLessThanOrEqual(previewSeconds(level - 1));
    for (let level = 4; level <= 30; level++) expect(previewSeconds(level)).toBeLessThanOrEqual(1.5);
    expect(previewSeconds(6)).toBe(1);
    expect(() => previewSeconds(0)).toThrow(/previewSeconds: level must be an integer >= 1/);
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
