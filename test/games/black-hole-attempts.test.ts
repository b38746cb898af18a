/**
 * Black hole counts a level's attempts (games/black-hole/levels.ts `LevelRun.attempts`), so the
 * replay's clock can say which attempt it is timing: the clock is the attempt's own and goes back to 0
 * at each new one, which read as a clock jumping backwards (0.0 -> 1.7 -> 1.1 s) when unnamed.
 */
import { describe, expect, test } from 'vitest';
import { startLevel, stepLevel } from '../../games/black-hole/levels';
import { createBlackHoleGame, setThrust } from '../../games/black-hole/rules';

describe('black hole: attempts', () => {
  test('none before the first thrust, one at lift-off, two after a fall and a new thrust; a new level starts from none', () => {
    const g = createBlackHoleGame({ seed: 1, lives: 9 });
    const run = startLevel(g, 4);
    for (let i = 0; i < 60; i++) stepLevel(g, run);
    expect(run.attempts).toBe(0);
    // ↑ held: level 4 has a hole across the straight path, so the climb falls in.
    setThrust(g, 'up');
    let event = stepLevel(g, run);
    expect(run.attempts).toBe(1);
    for (let i = 0; i < 1200 && event !== 'fell'; i++) event = stepLevel(g, run);
    expect(event).toBe('fell');
    expect(g.falls).toBe(1);
    setThrust(g, 'none');
    for (let i = 0; i < 30; i++) stepLevel(g, run);
    expect(run.attempts).toBe(1);
    setThrust(g, 'up');
    stepLevel(g, run);
    expect(run.attempts).toBe(2);
    expect(run.time - run.attemptStart).toBeCloseTo(g.world.dt, 9);
    expect(startLevel(g, 5).attempts).toBe(0);
  });
});
