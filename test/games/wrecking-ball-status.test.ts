/**
 * The wrecking-ball status line while a level is played (games/wrecking-ball/status.ts): on a phone
 * its numbers and one thing more, so it keeps to the three lines its bar holds; blocks down counted
 * toward the clear target; the cleared banner says what the clear asked and what still stands.
 */

import { describe, expect, it } from 'vitest';
import { COMPACT_EXTRAS, clearRuleLine, playStatusLine } from '../../games/wrecking-ball/status';

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
    // Past the target (pieces down while a drag is held): not 'down 17 of 16'.
    expect(playStatusLine({ ...playing, fallen: 17, extras: [] }, true)).toMatch(/ · down 17, 16 clear it$/);
  });

  it('the cleared banner names the clear target and the pieces left standing as spare', () => {
    // A stranger saw level 1 cleared with its tower of 6 still up and took the count for wrong:
    // the banner (4th line) now says the rule that cleared it and how many still stand.
    expect(clearRuleLine(1, 16, 6)).toBe('16 down clears level 1: the 6 still standing are spare');
    expect(clearRuleLine(2, 18, 1)).toBe('18 down clears level 2: the 1 still standing is spare');
    expect(clearRuleLine(1, 16, 0)).toBe('16 down clears level 1');
    expect(() => clearRuleLine(0, 16, 1)).toThrow(/clearRuleLine: level must be an integer >= 1, got 0/);
    expect(() => clearRuleLine(1, 16, -1)).toThrow(/clearRuleLine: standing must be an integer >= 0, got -1/);
  });
});
