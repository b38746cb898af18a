/**
 * The words over the field while black hole's ship waits at the start (games/black-hole/wait-words.ts),
 * driven by the events of real level steps: after a fall they say the fall; after a level begins, or
 * the ship is lost off the field, no word of an older fall is left (a stranger saw "Swallowed!
 * Practice: no life lost" over level 2's title, and "Swallowed! 2 lives left" over the status "Lost
 * in space").
 */

import { setPosition, setVelocity } from '@bitphysics/physics';
import { describe, expect, test } from 'vitest';
import { beginLevel, clearMessage, levelMessage, levelPoints, levelSpec, startLevel, stepLevel } from '../../games/black-hole/levels';
import { createBlackHoleGame, setThrust } from '../../games/black-hole/rules';
import {
  continueWords,
  nextHappening,
  pausedWords,
  READY_LINE,
  type ShipHappening,
  touchStatusLines,
  waitWords,
} from '../../games/black-hole/wait-words';

describe('black hole wait words', () => {
  test('after a game over the words say that Continue resets the score to 0, on the card and the status line, by keys or touch', () => {
    // A stranger lost the score on Continue with no word of it (the touch line said only "Tap to continue").
    for (const touch of [false, true]) {
      const w = continueWords(3, 1, touch);
      expect(w.card).toBe('Continue: level 3 again, score resets to 0');
      expect(w.status).toContain('continue from level 3 (score resets to 0).');
    }
    expect(continueWords(3, 1, true).status).toMatch(/^Tap /);
    expect(continueWords(3, 1, false).status).toBe('Enter: continue from level 3 (score resets to 0). R: start again from level 1.');
    expect(() => continueWords(0, 1, false)).toThrow(RangeError);
  });

  test('in the ready beat after a respawn the words say to wait, not how to fly on (a press then is dropped)', () => {
    // A stranger's "ok" press after a fall launched the new ship; presses in the beat are now dropped
    // (games/black-hole/main.ts READY_MS), so the words must not ask for one until it is over.
    for (const touch of [false, true])
      for (const [happening, lives] of [
        ['fell', 2],
        ['lost', 3],
      ] as const) {
        const ctx = { lives, practice: false, touch };
        const ready = waitWords(happening, { ...ctx, ready: true }).split('\n'),
          after = waitWords(happening, ctx).split('\n');
        expect(ready.at(-1)).toBe(READY_LINE);
        expect(after.at(-1)).toMatch(/^(Press|Tap) ↑, ← or → to fly on$/);
        // The rest (what happened, the lives) is the same in the beat and after it.
        expect(ready.slice(0, -1)).toEqual(after.slice(0, -1));
      }
  });

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
    expect(words()).toBe('Swallowed!\nPractice: no life lost\nPress ↑, ← or → to fly on');
    expect(words(true)).toBe('Swallowed!\nPractice: no life lost\nTap ↑, ← or → to fly on');
    // The ring taken and the ship set just under the line, climbing: the level is cleared; the next
    // begins. No fall words.
    setThrust(g, 'none');
    run.parked = false;
    run.ringsTaken = run.rings.length;
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
    expect(words()).toBe('Off the field!\nBack to the start, no life lost\nPress ↑, ← or → to fly on');
    // A fall on level 2 costs a life, and says how many are left.
    run.parked = false;
    setThrust(g, 'up');
    for (let k = 0; k < 1200 && e !== 'fell'; k++) last = nextHappening(last, (e = stepLevel(g, run)));
    expect(e).toBe('fell');
    expect(g.lives).toBe(2);
    expect(words()).toBe('Swallowed!\n2 lives left\nPress ↑, ← or → to fly on');
  });

  test('past the line with the ring left: the words say the ring was missed, not only "Off the field"', () => {
    const g = createBlackHoleGame({ seed: 3 });
    const run = startLevel(g, 1);
    expect(run.rings.length).toBe(1);
    let last: ShipHappening = 'level';
    // The ship set just under the line, climbing fast, the ring not taken: the line is closed, so it
    // flies on out of the top of the field.
    run.parked = false;
    setPosition(g.world, g.ship, [g.start[0], g.lineY - 0.01]);
    setVelocity(g.world, g.ship, [0, 6]);
    let e = '';
    for (let k = 0; k < 600 && e !== 'lost'; k++) last = nextHappening(last, (e = stepLevel(g, run)));
    expect(e).toBe('lost');
    expect(run.missedRing).toBe(true);
    const words = waitWords(last, { lives: g.lives, practice: run.spec.practice, touch: false, missedRing: run.missedRing });
    expect(words).toBe('Missed the ring!\nThe line counts after it: back to the start, no life lost\nPress ↑, ← or → to fly on');
    expect(g.message).toMatch(/^Missed the ring/);
    // Off a side edge, the ring still left: plain "Off the field".
    run.parked = false;
    setPosition(g.world, g.ship, [0.01, 3]);
    setVelocity(g.world, g.ship, [-2, 0]);
    e = '';
    for (let k = 0; k < 600 && e !== 'lost'; k++) last = nextHappening(last, (e = stepLevel(g, run)));
    expect(e).toBe('lost');
    expect(run.missedRing).toBe(false);
    expect(waitWords(last, { lives: g.lives, practice: false, touch: true, missedRing: run.missedRing })).toMatch(/^Off the field!/);
  });

  test('paused, the last line says how to resume (one message, not two stacked)', () => {
    expect(pausedWords('Swallowed!\n1 life left\nTap ↑, ← or → to fly on', 'Paused\n▶ to resume')).toBe(
      'Swallowed!\n1 life left\nPaused: ▶ to resume',
    );
    expect(pausedWords('Swallowed!\nGame over', 'Paused\nP to resume')).toBe('Swallowed!\nGame over\nPaused: P to resume');
    expect(pausedWords('', 'Paused\nP to resume')).toBe('');
  });

  test('bad lives throw, naming the function', () => {
    expect(() => waitWords('fell', { lives: -1, practice: false, touch: false })).toThrow(/waitWords: ctx.lives/);
    expect(waitWords('over', { lives: 0, practice: false, touch: false })).toBe('Swallowed!\nGame over');
  });
  test('touchStatusLines: a clear on a touch screen keeps the breakdown of its points in a shorter form before it drops it', () => {
    const summary = {
      level: 3,
      time: 9.4,
      totalTime: 21.7,
      falls: 2,
      points: 320,
      levelPoints: 300,
      bonus: 20,
      lives: 2,
      holes: 5,
      fuelLeft: Infinity,
    };
    const line = clearMessage(summary, false, 4);
    expect(line).toBe('Level 3 cleared in 9.4 s (21.7 s in all, 2 falls): +320 (300 + 20 speed bonus). Press Enter for level 4.');
    expect(touchStatusLines(line)).toEqual([
      'Level 3 cleared in 9.4 s (21.7 s in all, 2 falls): +320 (300 + 20 speed bonus). Tap for level 4.',
      'Level 3 cleared in 9.4 s: +320 (300 + 20 speed bonus). Tap for level 4.',
      'Level 3 cleared in 9.4 s: +320 (300 + 20 bonus). Tap for level 4.',
      'Level 3 cleared in 9.4 s: +320. Tap for level 4.',
    ]);
    // Every form keeps the points, the level cleared and the tap; a line with nothing to shorten is one form.
    for (const l of touchStatusLines(line)) expect(l).toMatch(/^Level 3 cleared in 9\.4 s.*\+320.*Tap for level 4\.$/);
    expect(touchStatusLines('Game over. Press Enter or R to play again.')).toEqual(['Game over. Tap to play again.']);
  });

  test("touchStatusLines: every level's opening line and a practice fall's have a form of two phone lines (100 characters at most)", () => {
    // The phone's status row holds two lines of some 55 characters (13 px type, 370 px): level 1's
    // opening line (132 characters) took three, and the field under it moved 10 px as the line changed.
    for (let level = 1; level <= 20; level++) {
      const forms = touchStatusLines(levelMessage(levelSpec(level)));
      const last = forms[forms.length - 1]!;
      expect(last.length, last).toBeLessThanOrEqual(100);
      // It still names the level and what the line is worth.
      expect(last).toMatch(new RegExp(`^Level ${level}: .*${levelPoints(level, 0).level} points`));
    }
    expect(touchStatusLines(levelMessage(levelSpec(1))).at(-1)).toBe(
      'Level 1: through the gold ring, then the green line: 100 points. Practice: falls cost no life.',
    );
    const fall = touchStatusLines('Swallowed by a black hole! Practice: falling in costs no life on this level. Steer round the red path.');
    expect(fall.at(-1)).toBe('Swallowed by a black hole! Practice: falls cost no life. Steer round the red path.');
  });
});
