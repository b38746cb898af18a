/**
 * The words over the field while black hole's ship waits at the start (games/black-hole/wait-words.ts),
 * driven by the events of real level steps: after a fall they say the fall; after a level begins, or
 * the ship is lost off the field, no word of an older fall is left (a stranger saw "Swallowed!
 * Practice: no life lost" over level 2's title, and "Swallowed! 2 lives left" over the status "Lost
 * in space").
 */

import { setPosition, setVelocity } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { beginLevel, startLevel, stepLevel } from '../../games/black-hole/levels';
import { createBlackHoleGame, setThrust } from '../../games/black-hole/rules';
import { nextHappening, pausedWords, type ShipHappening, waitWords } from '../../games/black-hole/wait-words';

describe('black hole wait words', () => {
  test('a fall, a clear, the next level, a loss: the words follow the last event only', () => {
    const g = createBlackHoleGame({ seed: 3 });
    const run = startLevel(g, 1);
    let last: ShipHappening = 'level';
    const words = (touch = false) => waitWords(last, { lives: g.lives, practice: run.spec.practice, touch });
    expect(words()).toBe('');
    // Held up, level 1's hole across the climb takes the ship (practice: no life lost).
    setThrust(g, 'up');
    let e = '';
    for (let k = 0; k < 600 && e !== 'fell'; k++) last = nextHappening(last, (e = stepLevel(g, run)));
    expect(e).toBe('fell');
    expect(words()).toBe('Swallowed!\nPractice: no life lost\nPress an arrow to fly on');
    expect(words(true)).toBe('Swallowed!\nPractice: no life lost\nTap an arrow to fly on');
    // The ship set just under the line, climbing: the level is cleared; the next begins. No fall words.
    setThrust(g, 'none');
    run.parked = false;
    setPosition(g.world, g.ship, [g.start[0], g.lineY - 0.01]);
    setVelocity(g.world, g.ship, [0, 2]);
    last = nextHappening(last, (e = stepLevel(g, run)));
    expect(e).toBe('cleared');
    expect(words()).toBe('');
    beginLevel(g, run);
    expect(run.spec.level).toBe(2);
    last = nextHappening(last, stepLevel(g, run));
    expect(words()).toBe('');
    // Off the left edge: lost, and the words say so, not the fall before.
    run.parked = false;
    setPosition(g.world, g.ship, [0.01, 3]);
    setVelocity(g.world, g.ship, [-2, 0]);
    last = nextHappening(last, (e = stepLevel(g, run)));
    expect(e).toBe('lost');
    expect(words()).toBe('Lost in space!\nBack to the start, no life lost\nPress an arrow to fly on');
    // A fall on level 2 costs a life, and says how many are left.
    run.parked = false;
    setThrust(g, 'up');
    for (let k = 0; k < 1200 && e !== 'fell'; k++) last = nextHappening(last, (e = stepLevel(g, run)));
    expect(e).toBe('fell');
    expect(g.lives).toBe(2);
    expect(words()).toBe('Swallowed!\n2 lives left\nPress an arrow to fly on');
  });

  test('paused, the last line says how to resume (one message, not two stacked)', () => {
    expect(pausedWords('Swallowed!\n1 life left\nTap an arrow to fly on', 'Paused\n▶ to resume')).toBe(
      'Swallowed!\n1 life left\nPaused: ▶ to resume',
    );
    expect(pausedWords('Swallowed!\nGame over', 'Paused\nP to resume')).toBe('Swallowed!\nGame over\nPaused: P to resume');
    expect(pausedWords('', 'Paused\nP to resume')).toBe('');
  });

  test('bad lives throw, naming the function', () => {
    expect(() => waitWords('fell', { lives: -1, practice: false, touch: false })).toThrow(/waitWords: ctx.lives/);
    expect(waitWords('over', { lives: 0, practice: false, touch: false })).toBe('Swallowed!\nGame over');
  });
});
