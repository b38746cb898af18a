/**
 * The wrecking-ball status line while a level is played (games/wrecking-ball/status.ts): on a phone
 * its numbers and one thing more, so it keeps to the three lines its bar holds; blocks down counted
 * toward the clear target.
 */

import { describe, expect, it } from 'vitest';
import { COMPACT_EXTRAS, playStatusLine } from '../../games/wrecking-ball/status';

const playing = {
  level: 1,
  score: 322,
  left: 2,
  budget: 5,
  par: 2,
  fallen: 15,
  target: 16,
  extras: [' · swinging back… hit in 1.2 s', ' · Hit at 4.8 m/s! 5 down', '', ' · hold Steady to stop the swing'],
};

describe('wrecking-ball status line', () => {
  it('on a phone: the numbers and the first thing more only; on a desktop every one', () => {
    // Before: every extra at once, 162 characters on a phone, four lines of its 12 px monospace at
    // 390 px (its bar holds three, 52 characters a line).
    expect(playStatusLine(playing, true)).toBe(
      'Level 1 · score 322 · swings left 2/5 (★★★ in 2) · down 15 of 16 to clear · swinging back… hit in 1.2 s',
    );
    expect(COMPACT_EXTRAS).toBe(1);
    expect(playStatusLine({ ...playing, extras: ['', '', ' · out of swings: tap ↻ to retry', ''] }, true)).toMatch(
      / to clear · out of swings: tap ↻ to retry$/,
    );
    expect(playStatusLine({ ...playing, score: null }, false)).toBe(
      'Level 1 · swings left 2/5 (★★★ in 2) · down 15 of 16 to clear · swinging back… hit in 1.2 s · Hit at 4.8 m/s! 5 down · hold Steady to stop the swing',
    );
  });

  it('counts blocks down toward the clear target: a cleared count reads as all that was asked', () => {
    // Before: 'down 16/27 (clear at 16)', a level half standing to a stranger when it cleared.
    expect(playStatusLine({ ...playing, fallen: 16, extras: [] }, true)).toContain('down 16 of 16 to clear');
    expect(playStatusLine({ ...playing, fallen: 16, extras: [] }, true)).not.toMatch(/\d+\/27/);
  });
});
