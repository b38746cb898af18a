/**
 * The wrecking-ball level-clear score's breakdown (games/wrecking-ball/scene.ts clearScore): the
 * banner's sum must be the score the page adds, and the stars' rule must say what swingStars does.
 */

import { describe, expect, it } from 'vitest';
import { clearReached, clearScore, clearScoreLine, starsRule, swingBudget, swingStars } from '../../games/wrecking-ball/scene';

describe('wrecking-ball clear score', () => {
  it("gives a stranger's jump from 396 to 1396 on a two-star clear, part by part", () => {
    // The figures: 396 points of blocks, then 1396 once the level cleared with ★★.
    const s = clearScore(396, 2);
    expect(s).toEqual({ blocks: 396, clear: 500, stars: 500, total: 1396 });
    expect(clearScoreLine(s, 2)).toBe('blocks 396 + clear 500 + ★★ 500 = 1396');
  });
  it('adds 250 a star over a 500 clear bonus, and its line sums to its total', () => {
    for (const [blocks, stars, total] of [
      [0, 0, 500],
      [120, 1, 870],
      [534, 3, 1784],
    ] as const) {
      const s = clearScore(blocks, stars);
      expect(s.total).toBe(total);
      const line = clearScoreLine(s, stars);
      const parts = line.split(' = ')[0]!.match(/\d+/g)!.map(Number);
      expect(parts.reduce((a, b) => a + b, 0)).toBe(Number(line.split(' = ')[1]));
    }
    expect(clearScoreLine(clearScore(10, 0), 0)).toBe('blocks 10 + clear 500 + no stars 0 = 510');
  });
  it('throws on blocks or stars out of range, naming the function', () => {
    expect(() => clearScore(-1, 2)).toThrow(/clearScore: blocks/);
    expect(() => clearScore(10, 4)).toThrow(/clearScore: stars/);
    expect(() => clearScore(10, 1.5)).toThrow(/clearScore: stars/);
  });
  it("states the stars' rule that swingStars applies, on levels 1 and 4", () => {
    expect(starsRule(1)).toBe('★★★ in ≤2 swings · ★★ in 3 · ★ in 4–5');
    expect(starsRule(4)).toBe('★★★ in ≤3 swings · ★★ in 4 · ★ in 5–6');
    // Each swing count the rule names earns the stars it says.
    for (const level of [1, 4]) {
      const [three, two, one] = starsRule(level).match(/\d+/g)!.map(Number);
      expect(swingStars(three!, true, level)).toBe(3);
      expect(swingStars(three! + 1, true, level)).toBe(2);
      expect(swingStars(two!, true, level)).toBe(2);
      expect(swingStars(one!, true, level)).toBe(1);
      expect(swingStars(swingBudget(level), true, level)).toBe(1);
    }
  });
  it('credits pieces felled while a drag is held to that swing once it is let go', () => {
    // The stranger's level 2: two swings used, the third drag held (the tagline drawing the ball
    // back) while the last pieces needed fell; then let go. The page fixes the swings when the
    // target is first reached (main.ts gameStep): it must name 3 swings, not 2.
    const frames = [
      { fallen: 5, swings: 2, pulling: false },
      { fallen: 8, swings: 2, pulling: true },
      { fallen: 13, swings: 2, pulling: true },
      { fallen: 13, swings: 2, pulling: true },
      { fallen: 13, swings: 3, pulling: false },
    ];
    const target = 10;
    const reachedWith = frames.find((f) => clearReached(f.fallen, target, f.pulling))?.swings;
    expect(reachedWith).toBe(3);
    expect(swingStars(reachedWith!, true, 2)).toBe(swingStars(3, true, 2));
    expect(clearReached(9, target, false)).toBe(false);
    expect(clearReached(10, target, false)).toBe(true);
  });
});
